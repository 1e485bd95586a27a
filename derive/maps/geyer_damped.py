"""Geyer et al.'s map with leg damping (report section 3.1, extended): declaration.

Not in the report: its leg is lossless. The radial solution is the damped oscillator of
:mod:`.geyer_damped_helpers` (derived and registry-checked there): under Assumption 1 (small
sweep; the angular momentum conserved, the damper exerting no torque about the toe) and the
first-order Taylor step of 1/(1+rho)^3 in (4),

    rho'' + 2 delta rho' + omega_n^2 rho = omega^2 - g_s / l0,
    delta = c / (2 m), omega_n^2 = k / m + 3 omega^2,
    rho(t) = a + exp(-delta t) (A cos(omega_D t) + B sin(omega_D t)), omega_D^2 = omega_n^2 - delta^2,

one half with k_c from the touchdown state, one with k_d from the bottom state (the report's
variable stiffness, as in section 5.1): a gait with damping needs k_d > k_c to put back what the
damper takes. The bottom is in closed form (:func:`bottom_trig`); the leg angle is (18)-(19)'s
integral of omega (1 - 2 rho) over the damped rho (:func:`angle_increment`), the rate the exact (17)
with the conserved momentum, as in Geyer's map. Liftoff (option ``liftoff``, the exact map's):
``force`` where the leg force k_d (l0 - q_r) - c q_rd falls to 0, or at q_r = q_r_lo if that comes
first; ``length`` at q_r = q_r_lo. Both are roots of a transcendental equation, found by Halley's
method safeguarded by bisection on [0, pi / omega_D] after the bottom, where rho increases
(:func:`liftoff_function`), from the closed-form root with the decay frozen at a quarter period
(:func:`frozen_decay_root`, the root itself at c = 0).

At c = 0 the map is Geyer's radial solution (11) split at its bottom, which agrees with ``geyer``
(k_c = k_d) to rounding (not bit for bit: ``geyer`` evaluates (11)-(14) in its own closed forms).
An overdamped leg (delta >= omega_n in a half) has no oscillation: status OVERDAMPED.
"""

from __future__ import annotations

from functools import cache
from typing import NamedTuple

import sympy as sp

from .. import catalog
from ..ir import Arg, Call, Field, Group, Guard, Iterate, Kernel, Stage, Step, Switch, sym
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..symbols import a, c, l0, m, omega, omega0, q_r_lo, q_r_td, q_rd_td, q_th_td, q_thd_td, t
from .exact import LIFTOFF
from .geyer_damped_helpers import (
    A_C,
    B_S,
    DELTA,
    OMEGA_D,
    RHO_D_TD,
    RHO_TD,
    damped_leg_angle,
    damped_radial_equation,
    damped_radial_solution,
)
from .gravity import HALF_EXTRAS, half_fixed_point, half_impulse_switch, iterations_option, tol_option

__all__ = [
    "MAPS",
    "PAGE",
    "angle_increment",
    "average_offset",
    "bottom_trig",
    "liftoff_function",
    "liftoff_kernel",
    "radial_state",
]

#: Placeholders of cos(omega_D t), sin(omega_D t) and exp(-delta t) at an event, so that each is
#: evaluated once at run time.
_COS, _SIN, _EXP = sp.symbols("C S X", real=True)
#: delta = c / (2 m), a kernel variable.
_DELTA = sym("delta")
_K_C, _K_D = catalog.PARAMS["k_c"].symbol, catalog.PARAMS["k_d"].symbol


def _trig(expr: sp.Basic) -> sp.Basic:
    """``expr`` with cos(omega_D t), sin(omega_D t), exp(+-delta t) replaced by the placeholders."""
    expr = sp.expand(expr)
    return expr.subs({sp.cos(OMEGA_D * t): _COS, sp.sin(OMEGA_D * t): _SIN}).subs(
        {sp.exp(-DELTA * t): _EXP, sp.exp(DELTA * t): 1 / _EXP}
    )


@cache
def radial_state() -> tuple[sp.Basic, sp.Basic, sp.Basic]:
    """rho, rho' and rho'' of the damped solution at a time t of its half, in the placeholders."""
    rho_t, _ = damped_radial_solution()
    rate = rho_t.diff(t)
    return _trig(rho_t), _trig(rate), _trig(rate.diff(t))


@cache
def angle_increment() -> sp.Basic:
    """(18)-(19) over a half: q_th(t) - q_th(0) = int_0^t omega (1 - 2 rho), in the placeholders."""
    cos_, sin_, decay = sp.cos(OMEGA_D * t), sp.sin(OMEGA_D * t), sp.exp(-DELTA * t)
    oscillation = A_C * (DELTA * cos_ - OMEGA_D * sin_) + B_S * (DELTA * sin_ + OMEGA_D * cos_)
    start = A_C * DELTA + B_S * OMEGA_D
    form = omega * (t * (1 - 2 * a) + 2 * (decay * oscillation - start) / (DELTA**2 + OMEGA_D**2))
    assert sp.simplify(form - damped_leg_angle()) == 0
    return form.subs({cos_: _COS, sin_: _SIN, decay: _EXP})


@cache
def bottom_trig() -> dict[sp.Symbol, sp.Basic]:
    """cos and sin of omega_D t_b at the bottom of the compression half, rho' = 0.

    rho' = exp(-delta t) (P cos(omega_D t) + R sin(omega_D t)) with P = rho'(0) < 0 (compressing):
    its first zero is omega_D t_b = pi/2 + atan(R / P) in (0, pi), where cos = R / h and
    sin = -P / h, h = sqrt(P^2 + R^2) (the kernel: with r = R / P, -r / sqrt(1 + r^2) and
    1 / sqrt(1 + r^2))."""
    _, rate, _ = radial_state()
    scaled = sp.expand(rate / _EXP)
    p_, r_ = scaled.coeff(_COS), scaled.coeff(_SIN)
    assert sp.simplify(scaled - p_ * _COS - r_ * _SIN) == 0
    coeffs = damped_radial_solution()[1]
    assert sp.simplify(p_.subs({A_C: coeffs[A_C], B_S: coeffs[B_S]}) - RHO_D_TD) == 0
    h = sp.sqrt(p_**2 + r_**2)
    return {"P": p_, "R": r_, _COS: r_ / h, _SIN: -p_ / h}


@cache
def average_offset() -> sp.Basic:
    """int_0^t (rho - a) dtau / t over a half (for type 4's average leg length), in the placeholders
    at its end t."""
    rho_t, _ = damped_radial_solution()
    tau = sp.Symbol("tau", positive=True)
    cos_, sin_, decay = sp.cos(OMEGA_D * t), sp.sin(OMEGA_D * t), sp.exp(-DELTA * t)
    form = (
        A_C * (DELTA + decay * (OMEGA_D * sin_ - DELTA * cos_))
        + B_S * (OMEGA_D - decay * (DELTA * sin_ + OMEGA_D * cos_))
    ) / (DELTA**2 + OMEGA_D**2)
    integral = sp.integrate(sp.expand(rho_t - a).subs(t, tau), (tau, 0, t))
    assert sp.simplify(form - integral) == 0
    return (form / t).subs({cos_: _COS, sin_: _SIN, decay: _EXP})


def _names(prefix: str) -> dict[sp.Symbol, sp.Symbol]:
    return {x: sym(prefix + x.name) for x in (a, OMEGA_D, A_C, B_S)}


def _bind(expr: sp.Basic, prefix: str, values: dict) -> sp.Basic:
    """``expr`` of a half in the kernel's names (``prefix``: the half's), then ``values`` (all at
    once)."""
    names = {**_names(prefix), DELTA: _DELTA}
    return expr.subs(names, simultaneous=True).subs(values, simultaneous=True)


def _half(prefix: str, stiffness: sp.Basic, rate: sp.Basic, rho0: sp.Basic, rhod0: sp.Basic) -> Stage:
    """The damped oscillator of one half (angular rate ``rate``) from its initial (rho0, rhod0): the
    offset a, omega_D and the amplitudes A, B, named ``prefix`` + a, omega_D, A_c, B_s."""
    wn2, rhs = damped_radial_equation()
    _, coeffs = damped_radial_solution()
    n = _names(prefix)
    at = {omega0: sp.sqrt(stiffness / m), omega: rate}
    wd2 = sym(prefix + "omega_D2")
    start = {RHO_TD: rho0, RHO_D_TD: rhod0}
    return Stage(
        (
            (n[a], (rhs / wn2).subs(at)),
            (wd2, wn2.subs(at) - _DELTA**2),
            (n[OMEGA_D], sp.sqrt(wd2)),
            (n[A_C], _bind(coeffs[A_C], prefix, start)),
            (n[B_S], _bind(coeffs[B_S], prefix, start)),
        ),
        (Guard(wd2 > 0, "OVERDAMPED", "omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)"),),
        comment=f"the damped radial solution of the {prefix.rstrip('_').split('_')[-1]} half",
    )


@cache
def _jerk() -> sp.Basic:
    """The third time derivative of rho of the damped solution at a time t of its half, in the
    placeholders (for Halley's step)."""
    rho_t, _ = damped_radial_solution()
    return _trig(rho_t.diff(t, 3))


@cache
def liftoff_function() -> tuple[sp.Basic, sp.Basic, sp.Basic, sp.Basic]:
    """g(t) after the bottom, whose first zero is liftoff, its first and second time derivatives, and
    the condition that the force decides it (rho increases on [0, pi / omega_D] there: rho' = -A
    (omega_n^2 / omega_D) exp(-delta t) sin(omega_D t), A < 0).

    ``length``: g = rho - rho_lo. ``force``: the leg force k_d (l0 - q_r) - c q_rd over k_d l0 is
    -(rho + 2 delta rho' / omega0^2); liftoff is the first of its zero and rho = rho_lo, so
    g = rho + max(2 delta rho' / omega0^2, -rho_lo) (at c = 0, rho - rho_lo: the same liftoff). A
    tie (c = 0, q_r_lo = l0) counts as the force's: the same state, and the derivatives with respect
    to c those from above (c -> 0+), as the exact map's."""
    rho_, rate, acc = radial_state()
    rho_lo = q_r_lo / l0 - 1
    w0sq = _K_D / m
    pull = 2 * DELTA * rate / w0sq
    by_force = (pull >= -rho_lo) & LIFTOFF.is_("force")
    g = rho_ + sp.Piecewise((pull, by_force), (-rho_lo, True))
    dg = rate + sp.Piecewise((2 * DELTA * acc / w0sq, by_force), (0, True))
    ddg = acc + sp.Piecewise((2 * DELTA * _jerk() / w0sq, by_force), (0, True))
    return g, dg, ddg, by_force


class LiftoffForm(NamedTuple):
    """A liftoff condition after the bottom as c0 + exp(-delta t) (P cos(omega_D t) + Q sin(omega_D t))
    = 0."""

    c0: sp.Basic
    P: sp.Basic
    Q: sp.Basic


@cache
def liftoff_forms() -> dict[str, LiftoffForm]:
    """Each liftoff condition in the form :class:`LiftoffForm`: ``length`` rho = rho_lo, ``force``
    rho + 2 delta rho' / omega0^2 = 0 (the leg force's zero)."""
    rho_, rate, _ = radial_state()
    forms = {"length": rho_ - (q_r_lo / l0 - 1), "force": rho_ + 2 * DELTA * rate / (_K_D / m)}
    out = {}
    for name, g in forms.items():
        c0 = g.subs(_EXP, 0)
        scaled = sp.expand((g - c0) / _EXP)
        p_, q_ = scaled.coeff(_COS), scaled.coeff(_SIN)
        assert sp.simplify(scaled - p_ * _COS - q_ * _SIN) == 0
        out[name] = LiftoffForm(c0, p_, q_)
    return out


def frozen_decay_root(form: LiftoffForm, growth: sp.Basic, w_d: sp.Basic) -> sp.Basic:
    """Near the root t of c0 + exp(-delta t) (P cos(omega_D t) + Q sin(omega_D t)) = 0: the root
    with the decay frozen at a time t_f (``growth`` = exp(delta t_f)), P cos x + Q sin x = -H
    cos(x + phi) (H = sqrt(P^2 + Q^2), tan phi = Q / -P, P < 0 after the bottom), so omega_D t =
    acos(c0 exp(delta t_f) / H) - phi (the argument clamped to [-1, 1]), with phi by its first order
    Q / -P (|phi| is of the order delta / omega_D). The root itself at delta = 0, where Q = 0."""
    c0, p_, q_ = form.c0, form.P, form.Q
    z = c0 * growth / sp.sqrt(p_**2 + q_**2)
    z = sp.Piecewise((-1, z < -1), (1, z > 1), (z, True))
    return (sp.acos(z) + q_ / p_) / w_d


#: Halley's iteration stops once a Halley step (not a bisection) moves the time by at most this share
#: of half a damped period: the iterate that step took is then the root to rounding (cubic
#: convergence: its error is of the order (omega_D half)^2 s^3 for a step s).
LIFTOFF_STEP_TOL = sp.Float(1e-6)

#: A step of the liftoff iteration of at most this much in omega_D t (and in delta t) moves cos,
#: sin and exp by their Taylor polynomials (degrees 6, 7, 7: truncation below 3e-21).
_SMALL_STEP = sp.Float(1e-2)


def _advance(w_d, delta, tau, tau_next, at: tuple) -> tuple[Step, ...]:
    """``_cos_next``, ``_sin_next``, ``_exp_next`` at ``tau_next`` from their values ``at`` ``tau``:
    a small step (at most :data:`_SMALL_STEP` in omega_D t and delta t) rotates and scales them by
    the Taylor polynomials of cos, sin and exp, a larger one evaluates them. Near the root every
    step is small, so the iterate the loop stops at costs no transcendental function."""
    cos_t, sin_t, exp_t = at
    u, v = sym("_du"), sym("_dv")
    cu = 1 - u**2 / 2 + u**4 / 24 - u**6 / 720
    su = u - u**3 / 6 + u**5 / 120 - u**7 / 5040
    ev = sum(v**i / sp.factorial(i) for i in range(8))
    small = (sp.Abs(u) <= _SMALL_STEP) & (sp.Abs(v) <= _SMALL_STEP)
    return (
        Stage(
            ((u, w_d * (tau_next - tau)), (v, -delta * (tau_next - tau))),
            comment="the step in omega_D t and in -delta t",
        ),
        Stage(
            (
                (
                    sym("_cos_next"),
                    sp.Piecewise((cos_t * cu - sin_t * su, small), (sp.cos(w_d * tau_next), True)),
                ),
                (
                    sym("_sin_next"),
                    sp.Piecewise((sin_t * cu + cos_t * su, small), (sp.sin(w_d * tau_next), True)),
                ),
                (sym("_exp_next"), sp.Piecewise((exp_t * ev, small), (sp.exp(-delta * tau_next), True))),
            ),
            comment="cos, sin, exp at the next iterate: Taylor steps when it is close",
        ),
    )


#: The outputs of :func:`liftoff_kernel`.
_LIFTOFF_OUT = ("tau", "cos_t", "sin_t", "exp_t", "by_force")


@cache
def liftoff_kernel() -> Kernel:
    """Liftoff after the bottom: the first zero of :func:`liftoff_function`'s g on (0, pi / omega_D),
    by Halley's method safeguarded by bisection on its bracket, from the root of one condition with
    the decay frozen at a quarter of the damped period (:func:`frozen_decay_root`; the root at
    c = 0)."""
    g, dg, ddg, by_force = liftoff_function()
    args = tuple(
        Arg(sym(x.name), doc)
        for x, doc in (
            (a, "offset a of the decompression half's rho(t)"),
            (OMEGA_D, "its damped frequency omega_D [rad/s]"),
            (A_C, "its amplitude A of exp(-delta t) cos(omega_D t)"),
            (B_S, "its amplitude B of exp(-delta t) sin(omega_D t)"),
        )
    ) + (
        Arg(_DELTA, "decay rate delta = c / (2 m) [1/s]"),
        catalog.PARAMS["m"],
        catalog.PARAMS["l0"],
        catalog.PARAMS["k_d"],
        catalog.PARAMS["q_r_lo"],
        LIFTOFF.arg(),
    )
    plain = {x: sym(x.name) for x in (a, OMEGA_D, A_C, B_S)}
    w_d = plain[OMEGA_D]

    def bind(expr, values):
        return expr.subs({**plain, DELTA: _DELTA}, simultaneous=True).subs(values, simultaneous=True)

    tau, lo, hi, half = sym("tau"), sym("_lo"), sym("_hi"), sym("_half")
    cos_t, sin_t, exp_t = sym("cos_t"), sym("sin_t"), sym("exp_t")
    at_t = {_COS: cos_t, _SIN: sin_t, _EXP: exp_t}
    g_v, g_d, g_dd, step = sym("_g"), sym("_dg"), sym("_ddg"), sym("_halley")
    lo_next, hi_next = sym("_lo_next"), sym("_hi_next")
    halley, bisections, bisections_next = sym("_bisect"), sym("_bisections"), sym("_bisections_next")
    # the first iterate from one condition's form: the force's where it is first (c > 0 with
    # q_r_lo = l0: at rho = 0 the leg already pulls), else the length's (at c = 0 the first zero is
    # rho = rho_lo; with q_r_lo < l0 and c > 0 either may be first, the length's root lies in the
    # bracket)
    forms = {name: LiftoffForm(*(bind(x, {}) for x in form)) for name, form in liftoff_forms().items()}
    by_force_form = LIFTOFF.is_("force") & (_DELTA > 0) & (q_r_lo >= l0)
    names = LiftoffForm(sym("_form_c"), sym("_form_p"), sym("_form_q"))
    chosen = tuple(
        (n, sp.Piecewise((f, by_force_form), (ln, True)))
        for n, f, ln in zip(names, forms["force"], forms["length"], strict=True)
    )

    # g at the bottom (rho' = 0) and half a damped period later (rho' = 0 again)
    g_start = bind(g, {_COS: 1, _SIN: 0, _EXP: 1})
    decay = sym("_decay_quarter")  # exp(-delta t) a quarter damped period after the bottom
    g_end = bind(g, {_COS: -1, _SIN: 0, _EXP: decay**2})
    return Kernel(
        name="damped_liftoff",
        summary="Liftoff of the damped decompression half: the first zero of the leg force (or of "
        "q_r - q_r_lo) after the bottom, safeguarded Halley.",
        equations=(),
        args=args,
        steps=(
            Stage(
                ((half, sp.pi / w_d), (decay, sp.exp(-_DELTA * half / 2))),
                (
                    Guard(plain[A_C] < 0, "RECOMPRESSION", "the k_d spring extends the leg at the bottom"),
                    Guard(g_start < 0, "NO_LIFTOFF", "the bottom lies below the liftoff"),
                    Guard(g_end > 0, "NO_LIFTOFF", "the leg reaches liftoff within half a damped period"),
                ),
                comment="liftoff lies in (0, pi / omega_D) after the bottom, where rho increases",
            ),
            Stage(chosen, comment="the form of the condition the first iterate solves"),
            Stage(
                ((sym("_first"), frozen_decay_root(names, 1 / decay, w_d)),),
                comment="the root with the decay frozen at a quarter period (the root itself at c = 0)",
            ),
            Stage(
                (
                    (sym("_tau0"), sp.Min(sp.Max(sym("_first"), 0), half)),
                    (sym("_cos0"), sp.cos(w_d * sym("_tau0"))),
                    (sym("_sin0"), sp.sin(w_d * sym("_tau0"))),
                    (sym("_exp0"), sp.exp(-_DELTA * sym("_tau0"))),
                ),
                comment="the first iterate, inside the bracket",
            ),
            Iterate(
                state=((tau, sym("_tau0")), (bisections, sp.S.Zero)),
                # the bracket and cos, sin, exp at the iterate move every pass, outside the test
                carry=(
                    (lo, sp.S.Zero, lo_next),
                    (hi, half, hi_next),
                    (cos_t, sym("_cos0"), sym("_cos_next")),
                    (sin_t, sym("_sin0"), sym("_sin_next")),
                    (exp_t, sym("_exp0"), sym("_exp_next")),
                ),
                body=(
                    Stage(
                        (
                            (g_v, bind(g, at_t)),
                            (g_d, bind(dg, at_t)),
                            (g_dd, bind(ddg, at_t)),
                        ),
                        comment="g and its derivatives at the iterate",
                    ),
                    Stage(
                        (
                            (lo_next, sp.Piecewise((tau, g_v < 0), (lo, True))),
                            (hi_next, sp.Piecewise((hi, g_v < 0), (tau, True))),
                            (step, tau - 2 * g_v * g_d / (2 * g_d**2 - g_v * g_dd)),
                        ),
                        comment="the bracket and Halley's step",
                    ),
                    Stage(
                        (
                            # g rises through its first zero: a step from where it does not, or one
                            # leaving the bracket, bisects instead
                            (
                                halley,
                                sp.Piecewise(
                                    (0, (g_d > 0) & (step >= lo_next) & (step <= hi_next)), (1, True)
                                ),
                            ),
                            (
                                sym("_tau_next"),
                                sp.Piecewise((step, sp.Eq(halley, 0)), ((lo_next + hi_next) / 2, True)),
                            ),
                            (bisections_next, bisections + halley),
                        ),
                        comment="Halley's step where it is safe, else bisection (counted: the loop stops "
                        "on Halley steps only)",
                    ),
                    *_advance(w_d, _DELTA, tau, sym("_tau_next"), (cos_t, sin_t, exp_t)),
                ),
                update=(sym("_tau_next"), bisections_next),
                max_iter=sp.Integer(60),
                tol=LIFTOFF_STEP_TOL,
                # a bisection moves the count by 1: no stop there, however small the step
                scales=(half, sp.S.One),
                count=sym("_passes"),
                comment="Halley's method on g, safeguarded by bisection on its bracket",
            ),
            Stage(
                ((sym("by_force"), sp.Piecewise((1, bind(by_force, at_t)), (0, True))),),
                comment="1 where the leg force decides liftoff, 0 where q_r = q_r_lo does",
            ),
        ),
        outputs=Group(
            "",
            (
                Field("tau", "liftoff time after the bottom", "s"),
                Field("cos_t", "cos(omega_D tau)", ""),
                Field("sin_t", "sin(omega_D tau)", ""),
                Field("exp_t", "exp(-delta tau)", ""),
                Field("by_force", "1: the leg force's zero, 0: q_r = q_r_lo", ""),
            ),
        ),
        check_inputs=False,
        check_outputs=False,
        module="geyer_damped",
    )


GRAVITY = Option(
    "gravity",
    "virtual gravity effect on p_th per half (report section 4 on [t_td, t_b] and [t_b, t_lo], as "
    "geyer-vs's types 3-4): (48) from the torque at each half's two ends with the type's leg length; "
    "each half runs with its mean momentum, the rates with the momentum at that instant",
    "none",
    (
        ("none", "p_th conserved (Assumption 1; the damper exerts no torque about the toe)"),
        ("type0", "(48) per half with the leg length l0 (type 0, (49))"),
        ("type1", "(48) per half with the leg length (l0 + q_r_b)/2 (type 1, (52))"),
        ("type2", "(48) per half with the stance-average leg length of the damped rho(t) (type 2, (62))"),
        ("type3", "(65) per half: the trapezoid rule on the torque at the half's ends"),
        ("type4", "(76) per half: the torque at the half's average leg length of the damped rho(t)"),
    ),
    roles=("accuracy-variants",),
)


class _Names:
    """Kernel names of one pass (``prefix`` + name)."""

    def __init__(self, prefix: str):
        self.prefix = prefix

    def __call__(self, name: str) -> sp.Symbol:
        return sym(self.prefix + name)


def _pass(n: _Names, P1: sp.Basic, P2: sp.Basic) -> tuple[Step, ...]:
    """The stance with the halves' virtual gravity effects P1, P2: every STANCE output (prefixed)."""
    rho_, rate, _ = radial_state()
    c_, d_ = n.prefix + "c_", n.prefix + "d_"
    cc, dd = _names(c_), _names(d_)
    p_, r_ = (_bind(bottom_trig()[x], c_, {}) for x in ("P", "R"))
    w1, w2 = n("omega_c"), n("omega_d")
    tb, q_r_b, p_b = n("t_bottom"), n("bottom_q_r"), n("p_b")
    cos_b, sin_b, exp_b = n("cos_b"), n("sin_b"), n("exp_b")
    at_b = {_COS: cos_b, _SIN: sin_b, _EXP: exp_b, t: tb, omega: w1}
    lo = {o: n(o) for o in _LIFTOFF_OUT}
    at_lo = {_COS: lo["cos_t"], _SIN: lo["sin_t"], _EXP: lo["exp_t"], t: lo["tau"], omega: w2}
    q_r_l = n("liftoff_q_r")
    pull = 2 * DELTA * rate / (_K_D / m)
    return (
        Stage(
            ((w1, (sym("p_td") + P1 / 2) / (m * l0**2)),),
            comment="eq (7): omega of the first half, from its mean momentum",
        ),
        _half(c_, _K_C, w1, q_r_td / l0 - 1, q_rd_td / l0),
        Stage(
            (
                (n("_P"), p_),
                (n("_R"), r_),
                # h = sqrt(P^2 + R^2) = -P sqrt(1 + (R/P)^2) (P < 0), free of overflow
                (n("_r"), n("_R") / n("_P")),
                (n("_s"), 1 / sp.sqrt(1 + n("_r") ** 2)),
                (tb, (sp.pi / 2 + sp.atan(n("_r"))) / cc[OMEGA_D]),
                (cos_b, -n("_r") * n("_s")),
                (sin_b, n("_s")),
                (exp_b, sp.exp(-_DELTA * tb)),
                (q_r_b, l0 * (1 + _bind(rho_, c_, at_b))),
                (n("bottom_q_rd"), sp.S.Zero),
                (n("bottom_q_th"), q_th_td + _bind(angle_increment(), c_, at_b)),
                (p_b, sym("p_td") + P1),
                (n("bottom_q_thd"), p_b / (m * q_r_b**2)),
                (w2, (p_b + P2 / 2) / (m * l0**2)),
            ),
            (Guard(q_r_b > 0, "FALL", "the leg collapses: bottom leg length q_r_b > 0"),),
            comment="the bottom (rho' = 0) in closed form; (19)'s angle, (17)'s rate",
        ),
        _half(d_, _K_D, w2, q_r_b / l0 - 1, sp.S.Zero),
        Call(
            liftoff_kernel(),
            {
                **{x.name: dd[x] for x in (a, OMEGA_D, A_C, B_S)},
                "delta": _DELTA,
                **{p: catalog.PARAMS[p].symbol for p in ("m", "l0", "k_d", "q_r_lo")},
                "liftoff": LIFTOFF.symbol,
            },
            {o: n.prefix + o for o in _LIFTOFF_OUT},
            comment="liftoff: the leg force's zero (or q_r = q_r_lo) after the bottom",
        ),
        Stage(
            (
                (n("t_stance"), tb + lo["tau"]),
                # at the force's zero rho = -2 delta rho' / omega0^2: exactly l0 at c = 0
                (
                    q_r_l,
                    sp.Piecewise(
                        (l0 * (1 - _bind(pull, d_, at_lo)), sp.Eq(lo["by_force"], 1)), (q_r_lo, True)
                    ),
                ),
                (n("liftoff_q_rd"), l0 * _bind(rate, d_, at_lo)),
                (n("liftoff_q_th"), n("bottom_q_th") + _bind(angle_increment(), d_, at_lo)),
                (n("liftoff_q_thd"), (p_b + P2) / (m * q_r_l**2)),
            ),
            (Guard(sp.Abs(n("liftoff_q_th")) < sp.pi / 2, "FALL", "the leg stays above horizontal"),),
            comment="the liftoff state: the damped solution at the root, (19)'s angle, (17)'s rate",
        ),
    )


def _impulses(inp: MapInputs, n: _Names) -> Switch:
    """``<prefix>P_new1``, ``<prefix>P_new2``: each half's stance impulse (types 0-4 of section 4 on
    [t_td, t_b] and [t_b, t_lo]) along the pass named by ``n``, types 2 and 4 with the average leg
    length of each half's damped rho(t) (:func:`average_offset`)."""
    c_, d_ = n.prefix + "c_", n.prefix + "d_"
    at_b = {_COS: n("cos_b"), _SIN: n("sin_b"), _EXP: n("exp_b"), t: n("t_bottom")}
    at_lo = {_COS: n("cos_t"), _SIN: n("sin_t"), _EXP: n("exp_t"), t: n("tau")}
    return half_impulse_switch(
        inp,
        n.prefix,
        (n("t_bottom"), n("t_stance")),
        (q_th_td, n("bottom_q_th"), n("liftoff_q_th")),
        (q_r_td, n("bottom_q_r"), n("bottom_q_r"), n("liftoff_q_r")),
        (
            l0 * (1 + _names(c_)[a] + _bind(average_offset(), c_, at_b)),
            l0 * (1 + _names(d_)[a] + _bind(average_offset(), d_, at_lo)),
        ),
        "the damped rho(t)",
    )


_P1, _P2 = sym("P_c_compression"), sym("P_c_decompression")
_TRIAL = _Names("i_")


def _steps(inp: MapInputs) -> tuple[Step, ...]:
    return (
        Stage(
            ((sym("p_td"), m * q_r_td**2 * q_thd_td), (_DELTA, c / (2 * m))),
            (Guard(q_rd_td < 0, "TOUCHDOWN_NOT_COMPRESSING", "stance starts compressing"),),
            comment="the touchdown angular momentum; delta = c / (2 m)",
        ),
        *half_fixed_point(inp, _TRIAL.prefix, _pass(_TRIAL, _P1, _P2), _impulses(inp, _TRIAL)),
    )


def _build(inp: MapInputs) -> MapBuild:
    steps = _steps(inp)

    def state_at(time: sp.Symbol) -> tuple[Step, ...]:
        """The polar state a time ``time`` after touchdown: the first half's damped solution before
        the bottom, the second's after it; the rates with the momentum at that instant."""
        rho_, rate, _ = radial_state()
        n = _TRIAL
        tb, ts = n("t_bottom"), n("t_stance")
        halves = []
        for half, t_half, th0, w in (
            ("c_", time, q_th_td, n("omega_c")),
            ("d_", time - tb, n("bottom_q_th"), n("omega_d")),
        ):
            prefix = n.prefix + half
            at = {
                _COS: sp.cos(_names(prefix)[OMEGA_D] * t_half),
                _SIN: sp.sin(_names(prefix)[OMEGA_D] * t_half),
                _EXP: sp.exp(-_DELTA * t_half),
                t: t_half,
                omega: w,
            }
            halves.append(
                (
                    l0 * (1 + _bind(rho_, prefix, at)),
                    l0 * _bind(rate, prefix, at),
                    th0 + _bind(angle_increment(), prefix, at),
                )
            )
        before = time < tb
        momentum = sp.Piecewise(
            (sym("p_td") + _P1 * time / tb, before), (n("p_b") + _P2 * (time - tb) / (ts - tb), True)
        )
        return steps + (
            Stage(
                (
                    (sym("q_r"), sp.Piecewise((halves[0][0], before), (halves[1][0], True))),
                    (sym("q_rd"), sp.Piecewise((halves[0][1], before), (halves[1][1], True))),
                    (sym("q_th"), sp.Piecewise((halves[0][2], before), (halves[1][2], True))),
                    (sym("q_thd"), momentum / (m * sym("q_r") ** 2)),
                ),
                comment="the damped solution of the half that holds t; the rate with the momentum at t",
            ),
        )

    return MapBuild(steps=steps, state_at=state_at, helpers=(liftoff_kernel(),))


#: The family page of this module's map (derive/maps/__init__.py): the page on leg damping.
PAGE = "damping"

MAPS = (
    MapSpec(
        name="geyer-damped",
        title="Geyer et al.'s map with leg damping (damped radial oscillator per half)",
        section="3.1",
        equations=("4", "7", "17", "18", "19", "48", "65", "76"),
        params=("m", "l0", "k_c", "k_d", "g_s", "c"),
        build=_build,
        options=(LIFTOFF, GRAVITY, iterations_option(100, ()), tol_option(1e-12)),
        extras=HALF_EXTRAS,
        summary="Assumption 1 (angular momentum conserved), 1/(1+rho)^3 by its Taylor polynomial: a "
        "damped linear oscillator per half (k_c, then k_d); liftoff a safeguarded Halley root; "
        "optionally a gravity correction per half",
        notes="Not in the report: (4) with the damper -c q_rd, linearised to rho'' + 2 delta rho' + "
        "omega_n^2 rho = omega^2 - g_s / l0 (delta = c / (2 m), omega_n^2 = k / m + 3 omega^2), solved "
        "from the touchdown state with k_c and from the bottom with k_d; the bottom in closed form; the "
        "leg angle (18)-(19) integrated over the damped rho; liftoff where the leg force or q_r - q_r_lo "
        "reaches 0 (option liftoff), by Halley's method safeguarded by bisection; option gravity adds "
        "a virtual gravity effect of section 4 (types 0-4) on each half.",
    ),
)
