"""Report section 4 (stance map with gravity correction): eqs 46-77, the virtual gravity effect P_c.

Each check compares a transcription of a printed display, typed as printed (errors included),
with the derivation of :mod:`slipmaps.derive.maps.gravity`: the torque (47) from Hamilton's
equations (29), the sample-mean impulse (48) and the average leg lengths of (11), (21) and (23)
integrated by SymPy. The sample-mean formulas of types 0-2, (49), (51), (52), (54), (62) and (64),
share one check factory (:func:`_sample_mean_row`); the five displays p_th_hat = p_th + P_c share
another (:func:`_corrected_momentum_row`). Two rows prove the report's claims that type 3 on
[t_td, t_lo] is type 0 and that type 4 on [t_td, t_lo] is type 2.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..maps import gravity
from ..maps.gravity import T_F, T_I
from ..model import mechanics
from ..symbols import (
    a,
    b,
    g_s,
    k_d,
    l0,
    m,
    omega0_hat,
    p_r,
    p_th,
    q_r,
    q_r_t,
    q_r_td,
    q_rd_td,
    q_th,
    q_th_t,
    q_th_td,
    q_thd_td,
    t,
)
from . import definition, equation, expect, expect_nonzero, expect_zero, forms

#: The report's subsections of section 4, each with its first equation number (46-48: the section's
#: opening, shared by every type).
SUBSECTIONS = (("4", 46), ("4.1", 49), ("4.2", 52), ("4.3", 55), ("4.4", 65), ("4.5", 67))

t0, t_td, t_lo, zeta = sp.symbols("t0 t_td t_lo zeta", real=True)
t_s = sp.Symbol("t_s", positive=True)
P_t0, P_c, p_th_hat, tau_sym = sp.symbols("P_t0 P_c p_th_hat tau", real=True)
P_OF_T = sp.Function("P", real=True)(t)  # the momentum P(t) of (46), (48)
q_th_b, q_th_lo = sp.symbols("q_th_b q_th_lo", real=True)
q_r_b = sp.Symbol("q_r_b", positive=True)
q_r_av = sp.Symbol("q_r_av", positive=True)  # the average leg length of (55)-(61), (67)-(75)
leg = sp.Symbol("L", positive=True)  # a constant leg length
g_printed = sp.Symbol("g", positive=True)  # the "g" of (48)
b_pos = sp.Symbol("b", positive=True)  # (21) and (23) hold for b > 0
q_rd_neg = sp.Symbol("q_rd_td", negative=True)  # touchdown on the compressing branch: q_rd_td < 0
Q_R, Q_TH = q_r_t.func, q_th_t.func  # q_r(t), q_th(t) of (65)
Q_R_AV = sp.Function("q_r_av", positive=True)  # q_r_av(t_i, t_f) of (76)
w = omega0_hat
C_23 = q_thd_td**2 * l0 - g_s  # the numerator (q_thd_td^2 l0 - g_s) of (23), (60)-(61), (73)-(75)


def _sines(*angles):
    return sum(sp.sin(th) for th in angles)


# --------------------------------------------------------------------------------------------
# Section 4: the gravity torque (46)-(47) and the sample-mean rule (48).


TAU = sp.Function("tau")  # the torque tau(t) of (46)


def _momentum_integral():
    """(46): P(t) = P_t0 + int_{t0}^{t} tau(zeta) dzeta, which solves dP/dt = tau from P(t0) = P_t0."""
    return P_t0 + sp.Integral(TAU(zeta), (zeta, t0, t))


@equation(
    "46",
    "momentum P(t) = P_t0 + int tau, from tau = dP/dt",
    "verified",
    "The printed integral solves dP/dt = tau with P(t0) = P_t0; with P = p_th, tau = dp_th/dt of (29) "
    "depends on the state only through (q_r, q_th), so (46) gives the stance momentum from the stance "
    "trajectory (the gravity sign is that of (29); (3)'s sign error is recorded in its row).",
    derived=lambda: forms((P_OF_T, _momentum_integral())),
)
def check_eq46() -> None:
    """Printed: tau(t) = dP(t)/dt <=> P(t) = P_t0 + int_{t0}^{t} tau(zeta) dzeta."""
    printed = _momentum_integral()
    expect_zero(sp.diff(printed, t) - TAU(t), "eq 46 d/dt of the printed P(t) equals tau(t)")
    expect_zero(printed.subs(t, t0).doit() - P_t0, "eq 46 the printed P(t) starts at P(t0) = P_t0")
    rate = mechanics.hamiltonian_vector_field()[3]  # dp_th/dt of (29)
    expect(
        not rate.has(p_th, p_r),
        "eq 46 dp_th/dt of (29) depends on neither momentum (the integral of (46) is explicit)",
    )


@equation(
    "47",
    "gravity torque tau = m g_s q_r sin q_th",
    "verified",
    "dp_th/dt, the fourth row of Hamilton's equations (29), whatever the stiffness.",
    derived=lambda: forms((tau_sym, gravity.torque())),
)
def check_eq47() -> None:
    """Printed: tau(t) = m g_s q_r(t) sin(q_th(t))."""
    printed = m * g_s * q_r * sp.sin(q_th)
    expect_zero(printed - gravity.torque(), "eq 47 printed tau equals dp_th/dt of (29)")
    expect_zero(
        printed - mechanics.hamiltonian_vector_field(k_d)[3],
        "eq 47 printed tau equals dp_th/dt of (29) with the decompression stiffness k_d",
    )


SAMPLE = sp.Symbol("k", integer=True, positive=True)  # the sample index of (48)
SAMPLE_RADIUS, SAMPLE_ANGLE = sp.IndexedBase("q_r"), sp.IndexedBase("q_th")  # q_r(t_k), q_th(t_k)


def _corrected_eq48(n):
    """(48) corrected: P_t0 + (t - t0) times the mean of (47) over the samples k = 1 ... n (a Sum)."""
    torque = m * g_s * SAMPLE_RADIUS[SAMPLE] * sp.sin(SAMPLE_ANGLE[SAMPLE])
    return P_t0 + (t - t0) * sp.Sum(torque, (SAMPLE, 1, n)) / n


@equation(
    "48",
    "sample-mean rule P(t) ~ P_t0 + (t - t0) mean of tau over n samples",
    "corrected",
    "Printed (1/n) sum_{k=1}^{n} m g q_r(n) sin(q_th(n)): n is both the number of samples and the "
    "sample index, so read literally every term is the n-th sample's and the mean collapses to "
    "m g q_r(n) sin q_th(n) (checked for n = 2, 3); g is the stance gravity g_s. Correct: P(t) ~ "
    "P_t0 + (t - t0) (1/n) sum_{k=1}^{n} m g_s q_r(t_k) sin(q_th(t_k)) over the samples t_k, "
    "gravity.impulse.",
    derived=lambda: forms((P_OF_T, _corrected_eq48(sp.Symbol("n", integer=True, positive=True)))),
)
def check_eq48() -> None:
    """Printed: P(t) = P_t0 + int_{t0}^{t} tau(zeta) dzeta
    ~ P_t0 + (t - t0) ((1/n) sum_{k=1}^{n} m g q_r(n) sin(q_th(n))).
    """
    idx, radius, angle = SAMPLE, SAMPLE_RADIUS, SAMPLE_ANGLE
    for n in (2, 3):
        printed = (
            P_t0 + (t - t0) * sp.Sum(m * g_printed * radius[n] * sp.sin(angle[n]), (idx, 1, n)).doit() / n
        )
        printed = printed.subs(g_printed, g_s)  # g read as g_s: what remains is the index
        corrected = _corrected_eq48(n).doit()
        derived = P_t0 + gravity.impulse(t - t0, [(radius[i], angle[i]) for i in range(1, n + 1)])
        expect_zero(
            printed - (P_t0 + (t - t0) * m * g_s * radius[n] * sp.sin(angle[n])),
            f"eq 48 printed mean over n = {n} samples is the n-th sample's torque alone",
        )
        expect_nonzero(
            printed - derived, f"eq 48 printed rule differs from the mean over {n} distinct samples"
        )
        expect_zero(
            corrected - derived, f"eq 48 corrected rule equals the mean of (47) over {n} distinct samples"
        )


# --------------------------------------------------------------------------------------------
# Factories: the sample-mean formulas of types 0-2 and the corrected momentum p_th_hat.


def _sample_mean_row(key: str, title: str, printed_text: str, coefficient, length, angles, note: str):
    """Register eq ``key``: printed P_c = t_s m g_s ``coefficient`` sum sin(``angles``), checked to be
    (48) over [t_td, t_lo] with the leg length held at ``length`` and one sample per angle."""
    what = f"eq {key} printed P_c equals (48) with q_r = {length} at {len(angles)} samples"

    def impulse():
        return gravity.impulse(t_s, [(length, th) for th in angles])

    def check() -> None:
        printed = t_s * m * g_s * coefficient * _sines(*angles)
        expect_zero(printed - impulse(), what)

    check.__doc__ = f"Printed: {printed_text}"
    check.__name__ = check.__qualname__ = f"check_eq{key}"
    return equation(key, title, "verified", note, derived=lambda: forms((P_c, sp.factor(impulse()))))(check)


_READINGS_NOTE = (
    "Suspected erratum: the report leaves open whether p_theta hat enters omega, omega0_hat, a and b "
    "or only the liftoff state; it says only 'we have only modified the parameter p_theta and rest of "
    "the formulation stays the same'. slipmaps offers both readings (option `reading` of the "
    "gravity-type maps): `report` = p_th + P_c everywhere; `mean` = trajectory with the stance-mean "
    "momentum p_th + P_c/2, which is what the constant torque of (48) integrates to (checked: at a "
    "constant leg length the torque P_c/t_s swept against 1/(m q_r^2) moves the leg angle as p_th + "
    "P_c/2 would, not as p_th + P_c), liftoff rate with p_th + P_c, liftoff radial speed from the "
    "energy (27). Both are measured in docs/accuracy.md."
)


def _corrected_momentum_row(key: str, title: str, source: str, start, duration, note: str):
    """Register eq ``key``: p_th_hat = p_th + P_c with P_c of ``source`` over [start, start + duration].

    Checks that p_th + P_c is the momentum (46) reaches at the end of the interval under the
    constant torque P_c/duration of (48), and that this torque sweeps the leg angle (at a constant
    leg length) as the mean momentum p_th + P_c/2, not as p_th + P_c.
    """

    def momentum():
        return p_th + sp.integrate(P_c / duration, (zeta, start, t))  # (46) with (48)'s torque

    def check() -> None:
        printed = p_th + P_c
        momentum_t = momentum()
        expect_zero(
            momentum_t.subs(t, start + duration) - printed,
            f"eq {key} printed p_th_hat is the momentum of (46) at the end of the interval of {source}",
        )
        sweep = sp.integrate(momentum_t / (m * leg**2), (t, start, start + duration))
        expect_zero(
            sweep - duration * (p_th + P_c / 2) / (m * leg**2),
            f"eq {key} the constant torque of (48) sweeps the leg angle as the mean momentum p_th + P_c/2",
        )
        expect_nonzero(
            sweep - duration * printed / (m * leg**2),
            f"eq {key} the sweep with p_th_hat throughout differs from that of the constant torque",
        )

    check.__doc__ = f"Printed: p_th_hat(t) = p_th + P_c(t), P_c of {source}."
    check.__name__ = check.__qualname__ = f"check_eq{key}"
    derived = lambda: forms((p_th_hat, sp.simplify(momentum().subs(t, start + duration))))  # noqa: E731
    return equation(key, title, "verified", note, derived=derived)(check)


def _momentum_note(source: str) -> str:
    return (
        f"As (50), with P_c of {source}: p_th + P_c is the momentum (46) reaches at liftoff under (48)'s "
        "constant torque; the same open reading."
    )


# --------------------------------------------------------------------------------------------
# Section 4.1: type 0, leg length l0 (49)-(51).

_sample_mean_row(
    "49",
    "type 0: P_c at l0, touchdown and liftoff samples",
    "P_c(t) = t_s m g_s l0/2 (sin(q_th_td) + sin(q_th_lo)).",
    l0 / 2,
    l0,
    (q_th_td, q_th_lo),
    "(48) over the stance t_s = t_lo - t_td with q_r = l0 at touchdown and liftoff. P_c(t) is a "
    "constant (the stance impulse) despite its (t); the prose after it lists q_th_td twice (q_th_lo "
    "meant).",
)

_corrected_momentum_row(
    "50",
    "corrected momentum p_th_hat = p_th + P_c (type 0)",
    "(49), (51)",
    t_td,
    t_s,
    "Checked: p_th + P_c is the momentum (46) reaches at liftoff under the constant torque P_c/t_s of "
    "(48). " + _READINGS_NOTE,
)

_sample_mean_row(
    "51",
    "type 0: P_c at l0, touchdown, bottom and liftoff samples",
    "P_c(t) = t_s m g_s l0/3 (sin(q_th_td) + sin(q_th_b) + sin(q_th_lo)).",
    l0 / 3,
    l0,
    (q_th_td, q_th_b, q_th_lo),
    "(48) with q_r = l0 at touchdown, bottom and liftoff.",
)


# --------------------------------------------------------------------------------------------
# Section 4.2: type 1, leg length (l0 + q_r_b)/2 (52)-(54).

_sample_mean_row(
    "52",
    "type 1: P_c at (l0 + q_r_b)/2, touchdown and liftoff samples",
    "P_c(t) = t_s m g_s (l0 + q_r_b)/4 (sin(q_th_td) + sin(q_th_lo)).",
    (l0 + q_r_b) / 4,
    (l0 + q_r_b) / 2,
    (q_th_td, q_th_lo),
    "(48) with q_r = (l0 + q_r_b)/2 at touchdown and liftoff: the 1/4 is the 1/2 of the leg length "
    "times the 1/2 of the mean.",
)
_corrected_momentum_row(
    "53",
    "corrected momentum p_th_hat = p_th + P_c (type 1)",
    "(52), (54)",
    t_td,
    t_s,
    _momentum_note("(52) or (54)"),
)
_sample_mean_row(
    "54",
    "type 1: P_c at (l0 + q_r_b)/2, touchdown, bottom and liftoff samples",
    "P_c(t) = t_s m g_s (l0 + q_r_b)/6 (sin(q_th_td) + sin(q_th_b) + sin(q_th_lo)).",
    (l0 + q_r_b) / 6,
    (l0 + q_r_b) / 2,
    (q_th_td, q_th_b, q_th_lo),
    "(48) with q_r = (l0 + q_r_b)/2 at touchdown, bottom and liftoff (1/6 = 1/2 * 1/3).",
)


# --------------------------------------------------------------------------------------------
# Average leg lengths, shared by type 2 (55)-(61) and type 4 (67)-(75).


@cache
def _average(source: str, t_from, t_to) -> sp.Basic:
    """gravity.average_leg_length on [t_from, t_to], read with b > 0 and q_rd_td < 0."""
    expr = gravity.average_leg_length(source).subs({T_I: t_from, T_F: t_to})
    return expr.subs({b: b_pos, q_rd_td: q_rd_neg})


def _integrand(source: str) -> sp.Basic:
    return gravity.stance_radius(source).subs({b: b_pos, q_rd_td: q_rd_neg})


def _read(expr) -> sp.Basic:
    """A printed form read with b > 0 and q_rd_td < 0 (touchdown compressing)."""
    return sp.sympify(expr).subs({b: b_pos, q_rd_td: q_rd_neg})


def _average_definition(source: str, t_from, t_to, lhs=q_r_av):
    """The derived form of an average's definition: ``lhs`` = the mean of q_r(t) of ``source``."""
    mean = sp.Integral(_integrand(source), (t, t_from, t_to)) / (t_to - t_from)
    return forms((lhs, mean))


def _expect_average_definition(key: str, integrand, source: str, t_from, t_to) -> None:
    """The printed integral definition: its integrand is q_r(t) of ``source``, its value the average."""
    integrand = _read(integrand)
    expect_zero(integrand - _integrand(source), f"eq {key} printed integrand equals q_r(t) of ({source[2:]})")
    value = sp.integrate(integrand, (t, t_from, t_to)) / (t_to - t_from)
    expect_zero(
        value - _average(source, t_from, t_to),
        f"eq {key} printed integral equals the average of q_r(t) of ({source[2:]}) on [{t_from}, {t_to}]",
    )


def _radius_11(time):
    return l0 * (1 + a + b * sp.sin(w * time))


def _radius_21(time):
    return l0 + l0 * (a * (1 - sp.cos(w * time)) - sp.sqrt(b**2 - a**2) * sp.sin(w * time))


def _radius_23(time):
    return l0 - sp.Abs(q_rd_td) / w * sp.sin(w * time) + C_23 / w**2 * (1 - sp.cos(w * time))


def _printed_average_11(t_from, t_to, duration):
    """(56), (57), (68) as printed: the b term lacks the factor l0."""
    return l0 * (1 + a) - b / (w * duration) * (sp.cos(w * t_to) - sp.cos(w * t_from))


def _corrected_average_11(t_from, t_to, duration):
    """(56), (57), (68) corrected: the integral of (11), l0 on the b term."""
    return l0 * (1 + a) - l0 * b / (w * duration) * (sp.cos(w * t_to) - sp.cos(w * t_from))


def _corrected_average_form(t_from, t_to, duration, lhs=q_r_av):
    """``lhs`` = corrected (56), (57) or (68)."""
    return forms((lhs, _corrected_average_11(t_from, t_to, duration)))


def _printed_eq59():
    root = sp.sqrt(b**2 - a**2)
    return l0 * (1 + a) - l0 / (t_s * w) * (a * sp.sin(w * t_s) + root * (1 - sp.cos(w * t_s)))


def _printed_eq61(speed):
    """(61) as printed with ``speed`` in the second term (printed: |q_r_td|, the leg length)."""
    return (
        l0
        + C_23 / w**2
        - sp.Abs(speed) / (w**2 * t_s) * (1 - sp.cos(w * t_s))
        - C_23 / (w**3 * t_s) * sp.sin(w * t_s)
    )


def _printed_average_21(t_from, t_to):
    """(71)-(72) as printed ((59) is the case [0, t_s])."""
    root = sp.sqrt(b**2 - a**2)
    bracket = a * (sp.sin(w * t_to) - sp.sin(w * t_from)) - root * (sp.cos(w * t_to) - sp.cos(w * t_from))
    return l0 * (1 + a) - l0 / ((t_to - t_from) * w) * bracket


def _printed_average_23(t_from, t_to):
    """(74)-(75) as printed, OCR read ((61) is the case [0, t_s])."""
    span = t_to - t_from
    return (
        l0
        + C_23 / w**2
        + sp.Abs(q_rd_td) / (w**2 * span) * (sp.cos(w * t_to) - sp.cos(w * t_from))
        - C_23 / (w**3 * span) * (sp.sin(w * t_to) - sp.sin(w * t_from))
    )


# --------------------------------------------------------------------------------------------
# Section 4.3: type 2, the stance-average leg length (55)-(64).


@equation(
    "55",
    "type 2: q_r_av = stance average of (11)",
    "verified",
    "The integrand is (11) in the absolute time of (11); the integral is gravity.average_leg_length.",
    derived=lambda: _average_definition("eq11", t_td, t_lo),
)
def check_eq55() -> None:
    """Printed: q_r_av = 1/(t_lo - t_td) int_{t_td}^{t_lo} l0 (1 + a + b sin(omega0_hat t)) dt."""
    _expect_average_definition("55", _radius_11(t), "eq11", t_td, t_lo)


_L0_NOTE = (
    "lacks a factor l0 on the b term (and is dimensionally inconsistent: b is a ratio): the integral "
    "of (11) is l0 (1 + a) - l0 b/(omega0_hat (t_f - t_i)) (cos(omega0_hat t_f) - cos(omega0_hat t_i)); "
    "the integral minus the printed form is -(l0 - 1) b (cos(omega0_hat t_f) - cos(omega0_hat t_i))/"
    "(omega0_hat (t_f - t_i)), zero only for l0 = 1. slipmaps uses the integral."
)


@equation(
    "56",
    "type 2: q_r_av from (11), closed form",
    "corrected",
    "Printed l0 (1 + a) - b/(omega0_hat (t_lo - t_td)) (cos(omega0_hat t_lo) - cos(omega0_hat t_td)) "
    + _L0_NOTE.replace("t_f", "t_lo").replace("t_i", "t_td"),
    derived=lambda: _corrected_average_form(t_td, t_lo, t_lo - t_td),
)
@equation(
    "57",
    "type 2: q_r_av from (11), with t_s",
    "corrected",
    "(56) with t_lo - t_td = t_s, the same missing l0: correct l0 (1 + a) - l0 b/(omega0_hat t_s) "
    "(cos(omega0_hat t_lo) - cos(omega0_hat t_td)).",
    derived=lambda: _corrected_average_form(t_td, t_td + t_s, t_s),
)
def check_eq56_57() -> None:
    """Printed: (56) q_r_av = l0 (1 + a) - b/(omega0_hat (t_lo - t_td))
                               (cos(omega0_hat t_lo) - cos(omega0_hat t_td));
    (57) q_r_av = l0 (1 + a) - b/(omega0_hat t_s) (cos(omega0_hat t_lo) - cos(omega0_hat t_td)).
    """
    cases = (
        ("56", t_td, t_lo, t_lo - t_td),
        ("57", t_td, t_td + t_s, t_s),
    )
    for key, t_from, t_to, duration in cases:
        derived = _average("eq11", t_from, t_to)
        printed = _read(_printed_average_11(t_from, t_to, duration))
        corrected = _read(_corrected_average_11(t_from, t_to, duration))
        offset = (l0 - 1) * b_pos * (sp.cos(w * t_to) - sp.cos(w * t_from)) / (w * duration)
        expect_nonzero(printed - derived, f"eq {key} printed q_r_av differs from the integral of (11)")
        expect_zero(
            derived - printed + offset, f"eq {key} integral of (11) minus printed is -(l0 - 1) b (...)"
        )
        expect_zero(corrected - derived, f"eq {key} corrected q_r_av (l0 on the b term) equals the integral")


@equation(
    "58",
    "type 2: q_r_av = stance average of (21)",
    "verified",
    "The integrand is (21) (touchdown at t = 0, q_r_td = l0, b > 0); the integral is "
    "gravity.average_leg_length on [0, t_s].",
    derived=lambda: _average_definition("eq21", 0, t_s),
)
def check_eq58() -> None:
    """Printed: q_r_av = 1/t_s int_0^{t_s} (l0 + l0 [a (1 - cos(omega0_hat t))
    - sqrt(b^2 - a^2) sin(omega0_hat t)]) dt.
    """
    _expect_average_definition("58", _radius_21(t), "eq21", 0, t_s)


@equation(
    "59",
    "type 2: q_r_av from (21), closed form",
    "verified",
    "The integral of (58), b > 0.",
    derived=lambda: forms((q_r_av, _average("eq21", 0, t_s))),
)
def check_eq59() -> None:
    """Printed: q_r_av = l0 (1 + a) - l0/(t_s omega0_hat) [a sin(omega0_hat t_s)
    + sqrt(b^2 - a^2) (1 - cos(omega0_hat t_s))].
    """
    expect_zero(
        _read(_printed_eq59()) - _average("eq21", 0, t_s), "eq 59 printed q_r_av equals the integral of (21)"
    )


@equation(
    "60",
    "type 2: q_r_av = stance average of (23)",
    "verified",
    "The integrand is (23) with the radial speed |q_rd_td| (printed with the dot here; see (23)); "
    "touchdown compressing (q_rd_td < 0), omega0_hat = sqrt(k/m + 3 q_thd_td^2).",
    derived=lambda: _average_definition("eq23", 0, t_s),
)
def check_eq60() -> None:
    """Printed: q_r_av = 1/t_s int_0^{t_s} (l0 - |q_rd_td|/omega0_hat sin(omega0_hat t)
    + (q_thd_td^2 l0 - g_s)/omega0_hat^2 (1 - cos(omega0_hat t))) dt.
    """
    _expect_average_definition("60", _radius_23(t), "eq23", 0, t_s)


@equation(
    "61",
    "type 2: q_r_av from (23), closed form",
    "corrected",
    "Printed |q_r_td| (the leg length; the term would be in m s, not m), as in (23) and (25); the "
    "integral of (60) has the radial speed |q_rd_td|: q_r_av = l0 + (q_thd_td^2 l0 - g_s)/omega0_hat^2 "
    "- |q_rd_td|/(omega0_hat^2 t_s) (1 - cos(omega0_hat t_s)) - (q_thd_td^2 l0 - g_s)/(omega0_hat^3 t_s) "
    "sin(omega0_hat t_s).",
    derived=lambda: forms((q_r_av, _printed_eq61(q_rd_td))),
)
def check_eq61() -> None:
    """Printed: q_r_av = l0 + (q_thd_td^2 l0 - g_s)/omega0_hat^2
    - |q_r_td|/(omega0_hat^2 t_s) (1 - cos(omega0_hat t_s))
    - (q_thd_td^2 l0 - g_s)/(omega0_hat^3 t_s) sin(omega0_hat t_s).
    """
    average = _average("eq23", 0, t_s)
    expect_nonzero(
        _read(_printed_eq61(q_r_td)) - average,
        "eq 61 as printed (|q_r_td|) differs from the integral of (23)",
    )
    expect_zero(_read(_printed_eq61(q_rd_td)) - average, "eq 61 with |q_rd_td| equals the integral of (23)")


_sample_mean_row(
    "62",
    "type 2: P_c at q_r_av, touchdown and liftoff samples",
    "P_c(t) = t_s m g_s q_r_av/2 (sin(q_th_td) + sin(q_th_lo)).",
    q_r_av / 2,
    q_r_av,
    (q_th_td, q_th_lo),
    "(48) with q_r = q_r_av of (55)-(61) at touchdown and liftoff.",
)
_corrected_momentum_row(
    "63",
    "corrected momentum p_th_hat = p_th + P_c (type 2)",
    "(62), (64)",
    t_td,
    t_s,
    _momentum_note("(62) or (64)"),
)
_sample_mean_row(
    "64",
    "type 2: P_c at q_r_av, touchdown, bottom and liftoff samples",
    "P_c(t) = t_s m g_s q_r_av/3 (sin(q_th_td) + sin(q_th_b) + sin(q_th_lo)).",
    q_r_av / 3,
    q_r_av,
    (q_th_td, q_th_b, q_th_lo),
    "(48) with q_r = q_r_av of (55)-(61) at touchdown, bottom and liftoff.",
)


# --------------------------------------------------------------------------------------------
# Section 4.4: type 3, the trapezoid rule on [t_i, t_f] (65)-(66).


def _trapezoid_impulse():
    """(65) derived: (48) on [t_i, t_f] with the true leg lengths and angles at t_i and t_f."""
    return gravity.impulse(T_F - T_I, [(Q_R(T_I), Q_TH(T_I)), (Q_R(T_F), Q_TH(T_F))])


def _printed_eq65(t_from, t_to):
    return (
        (t_to - t_from) * m * g_s / 2 * (Q_R(t_from) * sp.sin(Q_TH(t_from)) + Q_R(t_to) * sp.sin(Q_TH(t_to)))
    )


@equation(
    "65",
    "type 3: P_c by the trapezoid rule on [t_i, t_f]",
    "verified",
    "(48) on [t_i, t_f] (t_td <= t_i < t_f <= t_lo) with the true leg lengths and angles at t_i and "
    "t_f as the 2 samples.",
    derived=lambda: forms((P_c, sp.factor(_trapezoid_impulse()))),
)
def check_eq65() -> None:
    """Printed: P_c(t) = (t_f - t_i) m g_s/2 [q_r(t_i) sin(q_th(t_i)) + q_r(t_f) sin(q_th(t_f))]."""
    derived = _trapezoid_impulse()
    expect_zero(_printed_eq65(T_I, T_F) - derived, "eq 65 printed P_c equals (48) at t_i and t_f")


_corrected_momentum_row(
    "66",
    "corrected momentum p_th_hat = p_th + P_c (type 3)",
    "(65)",
    T_I,
    T_F - T_I,
    "As (50), with P_c of (65) on [t_i, t_f]: p_th + P_c is the momentum (46) reaches at t_f from p_th "
    "at t_i under (48)'s constant torque; the same open reading.",
)


@equation(
    "sec4.4-claim",
    "claim: type 3 on [t_td, t_lo] with q_r_td = q_r_lo = l0 is type 0",
    "verified",
    "Holds: (65) with t_i = t_td, t_f = t_lo and q_r(t_td) = q_r(t_lo) = l0 is (49) (the 2-sample "
    "type 0), for the printed forms and for (48).",
)
def check_type3_is_type0() -> None:
    """Printed (4.4): "A special case of initial and final state times are touchdown and liftoff
    times, and also if touchdown and liftoff leg lengths are set to be rest leg length, then correction
    type 3 is the same as correction type 0."
    """
    special = {Q_R(t_td): l0, Q_R(t_lo): l0, Q_TH(t_td): q_th_td, Q_TH(t_lo): q_th_lo}
    type3 = _printed_eq65(t_td, t_lo).subs(special).subs(t_lo, t_td + t_s)
    type0 = t_s * m * g_s * l0 / 2 * _sines(q_th_td, q_th_lo)  # (49) as printed
    expect_zero(type3 - type0, "sec4.4 printed (65) on [t_td, t_lo] with q_r_td = q_r_lo = l0 equals (49)")
    derived3 = _trapezoid_impulse()
    derived3 = derived3.subs({T_I: t_td, T_F: t_lo}).subs(special).subs(t_lo, t_td + t_s)
    derived0 = gravity.impulse(t_s, [(l0, q_th_td), (l0, q_th_lo)])
    expect_zero(derived3 - derived0, "sec4.4 (48) with the true leg lengths at l0 equals (48) at q_r = l0")


# --------------------------------------------------------------------------------------------
# Section 4.5: type 4, the average leg length on [t_i, t_f] (67)-(77).


@equation(
    "67",
    "type 4: q_r_av(t_i, t_f) = average of (11)",
    "verified",
    "The integrand is (11) in its absolute time; the integral is gravity.average_leg_length.",
    derived=lambda: _average_definition("eq11", T_I, T_F, Q_R_AV(T_I, T_F)),
)
def check_eq67() -> None:
    """Printed: q_r_av(t_i, t_f) = 1/(t_f - t_i) int_{t_i}^{t_f} l0 (1 + a + b sin(omega0_hat t)) dt."""
    _expect_average_definition("67", _radius_11(t), "eq11", T_I, T_F)


@equation(
    "68",
    "type 4: q_r_av(t_i, t_f) from (11), closed form",
    "corrected",
    "Printed l0 (1 + a) - b/(omega0_hat (t_f - t_i)) (cos(omega0_hat t_f) - cos(omega0_hat t_i)) "
    "(as (56)) " + _L0_NOTE,
    derived=lambda: _corrected_average_form(T_I, T_F, T_F - T_I, Q_R_AV(T_I, T_F)),
)
def check_eq68() -> None:
    """Printed: q_r_av(t_i, t_f) = l0 (1 + a) - b/(omega0_hat (t_f - t_i))
    (cos(omega0_hat t_f) - cos(omega0_hat t_i)).
    """
    derived = _average("eq11", T_I, T_F)
    printed = _read(_printed_average_11(T_I, T_F, T_F - T_I))
    corrected = _read(_corrected_average_11(T_I, T_F, T_F - T_I))
    offset = (l0 - 1) * b_pos * (sp.cos(w * T_F) - sp.cos(w * T_I)) / (w * (T_F - T_I))
    expect_nonzero(printed - derived, "eq 68 printed q_r_av differs from the integral of (11)")
    expect_zero(derived - printed + offset, "eq 68 integral of (11) minus printed is -(l0 - 1) b (...)")
    expect_zero(corrected - derived, "eq 68 corrected q_r_av (l0 on the b term) equals the integral")


definition(
    "69",
    "(not in the OCR text) last line of the (11)-based display (67)-(68)",
    "The number 69 is missing from the OCR text (tags (67), (68), (70)). It must be the last line of "
    "the (11)-based display (67)-(68): that display mirrors the three-line (55)-(57), whose third line "
    "(57) restates (56) with t_s, while the (21)- and (23)-based displays of 4.5 keep three numbers "
    "each, (70)-(72) and (73)-(75); the OCR drops the last line of an aligned display elsewhere too "
    "((88) after the trailing '=' of (87), (95) after (94)). With no t_s in type 4 the line is empty or "
    "repeats (68) (then with (68)'s missing l0): no printed content to check.",
)


@equation(
    "70",
    "type 4: q_r_av(t_i, t_f) = average of (21)",
    "verified",
    "The integrand is (21) (t from touchdown: 'note that t_td = 0'; b > 0); the integral is "
    "gravity.average_leg_length.",
    derived=lambda: _average_definition("eq21", T_I, T_F, Q_R_AV(T_I, T_F)),
)
def check_eq70() -> None:
    """Printed: q_r_av(t_i, t_f) = 1/(t_f - t_i) int_{t_i}^{t_f} (l0 + l0 [a (1 - cos(omega0_hat t))
    - sqrt(b^2 - a^2) sin(omega0_hat t)]) dt.
    """
    _expect_average_definition("70", _radius_21(t), "eq21", T_I, T_F)


@equation(
    "71",
    "type 4: q_r_av(t_i, t_f) from (21), closed form (first line)",
    "verified",
    "(71)-(72) are one expression broken over two lines: the integral of (70), b > 0.",
    derived=lambda: forms((Q_R_AV(T_I, T_F), _printed_average_21(T_I, T_F))),
)
@equation(
    "72",
    "type 4: q_r_av(t_i, t_f) from (21), closed form (second line)",
    "verified",
    "Continuation of (71).",
    derived=lambda: forms((Q_R_AV(T_I, T_F), _printed_average_21(T_I, T_F))),
)
def check_eq71_72() -> None:
    """Printed: q_r_av(t_i, t_f) = l0 (1 + a) - l0/((t_f - t_i) omega0_hat) [a (sin(omega0_hat t_f)
    - sin(omega0_hat t_i))  (71)
    - sqrt(b^2 - a^2) (cos(omega0_hat t_f) - cos(omega0_hat t_i))]  (72).
    """
    expect_zero(
        _read(_printed_average_21(T_I, T_F)) - _average("eq21", T_I, T_F),
        "eqs 71-72 printed q_r_av(t_i, t_f) equals the integral of (21)",
    )


@equation(
    "73",
    "type 4: q_r_av(t_i, t_f) = average of (23)",
    "verified",
    "Untagged in the OCR text: the display's first line ends in the garble "
    "'d \\dot{t}_{\\prime}^{\\prime}' (dt and its tag). The integrand is (23) with |q_rd_td| as in "
    "(60) (t from touchdown, q_rd_td < 0); the integral is gravity.average_leg_length.",
    derived=lambda: _average_definition("eq23", T_I, T_F, Q_R_AV(T_I, T_F)),
)
def check_eq73() -> None:
    """Printed: q_r_av(t_i, t_f) = 1/(t_f - t_i) int_{t_i}^{t_f} (l0 - |q_rd_td|/omega0_hat sin(omega0_hat t)
    + (q_thd_td^2 l0 - g_s)/omega0_hat^2 (1 - cos(omega0_hat t))) dt
    (OCR: 'd \\dot{t}_{\\prime}^{\\prime}', the tag (73) garbled).
    """
    _expect_average_definition("73", _radius_23(t), "eq23", T_I, T_F)


@equation(
    "74",
    "type 4: q_r_av(t_i, t_f) from (23), closed form (first line)",
    "verified",
    "(74)-(75) are one expression broken over two lines: the integral of (73); |q_rd_td| printed "
    "with the dot here.",
    derived=lambda: forms((Q_R_AV(T_I, T_F), _printed_average_23(T_I, T_F))),
)
@equation(
    "75",
    "type 4: q_r_av(t_i, t_f) from (23), closed form (second line)",
    "verified",
    "Continuation of (74). OCR: q_{\\dot{\\theta}+t} read as q_thd_td.",
    derived=lambda: forms((Q_R_AV(T_I, T_F), _printed_average_23(T_I, T_F))),
)
def check_eq74_75() -> None:
    """Printed: q_r_av(t_i, t_f) = l0 + (q_thd_td^2 l0 - g_s)/omega0_hat^2
    + |q_rd_td|/(omega0_hat^2 (t_f - t_i)) [cos(omega0_hat t_f) - cos(omega0_hat t_i)]  (74)
    - (q_thd_td^2 l0 - g_s)/(omega0_hat^3 (t_f - t_i)) [sin(omega0_hat t_f) - sin(omega0_hat t_i)]  (75).
    """
    expect_zero(
        _read(_printed_average_23(T_I, T_F)) - _average("eq23", T_I, T_F),
        "eqs 74-75 printed q_r_av(t_i, t_f) equals the integral of (23)",
    )


def _average_length_impulse():
    """(76) derived: (48) on [t_i, t_f] at the leg length q_r_av(t_i, t_f), samples at t_i and t_f."""
    length = Q_R_AV(T_I, T_F)
    return gravity.impulse(T_F - T_I, [(length, Q_TH(T_I)), (length, Q_TH(T_F))])


def _printed_eq76(t_from, t_to):
    length = Q_R_AV(t_from, t_to)
    return (t_to - t_from) * m * g_s * length / 2 * _sines(Q_TH(t_from), Q_TH(t_to))


@equation(
    "76",
    "type 4: P_c at q_r_av(t_i, t_f), samples at t_i and t_f",
    "verified",
    "(48) on [t_i, t_f] with q_r = q_r_av(t_i, t_f) of (67)-(75) at t_i and t_f.",
    derived=lambda: forms((P_c, sp.factor(_average_length_impulse()))),
)
def check_eq76() -> None:
    """Printed: P_c(t) = (t_f - t_i) m g_s q_r_av(t_i, t_f)/2 (sin(q_th(t_i)) + sin(q_th(t_f)))."""
    derived = _average_length_impulse()
    expect_zero(_printed_eq76(T_I, T_F) - derived, "eq 76 printed P_c equals (48) at q_r_av(t_i, t_f)")


_corrected_momentum_row(
    "77",
    "corrected momentum p_th_hat = p_th + P_c (type 4)",
    "(76)",
    T_I,
    T_F - T_I,
    "As (50), with P_c of (76) on [t_i, t_f]: p_th + P_c is the momentum (46) reaches at t_f from p_th "
    "at t_i under (48)'s constant torque; the same open reading.",
)


@equation(
    "sec4.5-claim",
    "claim: type 4 on [t_td, t_lo] is type 2",
    "verified",
    "Holds: (76) on [t_td, t_lo] is (62); the averages agree as printed: (67) is (55), (68) is (56) "
    "(with the same missing l0), (70) and (71)-(72) on [0, t_s] are (58) and (59), (73) and (74)-(75) "
    "are (60) and (61) (OCR read).",
)
def check_type4_is_type2() -> None:
    """Printed (4.5): "A special case of initial and final state times are touchdown and liftoff
    times, for this special case correction type 4 is the same as correction type 2."
    """
    type4 = _printed_eq76(t_td, t_lo).subs(
        {Q_R_AV(t_td, t_lo): q_r_av, Q_TH(t_td): q_th_td, Q_TH(t_lo): q_th_lo}
    )
    type2 = t_s * m * g_s * q_r_av / 2 * _sines(q_th_td, q_th_lo)  # (62) as printed
    expect_zero(type4.subs(t_lo, t_td + t_s) - type2, "sec4.5 printed (76) on [t_td, t_lo] equals (62)")
    # (67), (70), (73) on [t_td, t_lo] are the integrals (55), (58), (60); their closed forms as printed:
    printed56 = l0 * (1 + a) - b / (w * (t_lo - t_td)) * (sp.cos(w * t_lo) - sp.cos(w * t_td))
    printed68 = _printed_average_11(T_I, T_F, T_F - T_I).subs({T_I: t_td, T_F: t_lo})
    expect_zero(printed68 - printed56, "sec4.5 printed (68) on [t_td, t_lo] equals printed (56)")
    expect_zero(
        _printed_average_21(0, t_s) - _printed_eq59(), "sec4.5 printed (71)-(72) on [0, t_s] equal (59)"
    )
    expect_zero(
        _printed_average_23(0, t_s) - _printed_eq61(q_rd_td),
        "sec4.5 printed (74)-(75) on [0, t_s] equal (61) with |q_rd_td|",
    )
