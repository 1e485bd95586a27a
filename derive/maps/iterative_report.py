"""Schwind and Koditschek's iteration as the report prints it (sections 3.2 and 5.2), whole stance.

The (n+1)-th iterate at a leg length x needs the n-th iterate at the mean-value point xi(x) only
((42)-(44), (124)-(126), (139)-(141)), so n iterations at the end of a half-stance are a *chain*:
the points x_0 (the end), x_{j+1} = xi(x_j), ..., x_n; the zeroth iterate evaluated at x_n; then n
steps outward, the step from x_{j+1} to x_j giving the (n-j)-th iterate at x_j from the
(n-j-1)-th at x_{j+1}. Each point is held as its offset e_j = x_j - a from the end a the
mean-value point is measured from (e_{j+1} = e_j/4 for the fraction 1/4 of (41), (123), (143)):
multiplying by 4 is exact in binary floating point, so the chain returns to x_0 exactly (x_n
itself rounds to a from about n = 26 on).

Each step takes h = H^{-1}(x_{j+1}, q_th, p_th, E) of (33)/(119)/(138) on the values at x_{j+1}
(real only when its radicand is positive: else status IMAGINARY_MOMENTUM) and, with s the sign of
p_r (-1 compression, +1 decompression) and (T_a, Q_a, P_a) the values at the end a the integrals
start from:

- variant "integrand" (42)-(44), (124)-(126), (139)-(141): the whole integrand at the point,
  Q = Q_a + P/(s h x_{j+1}^2) (x_j - a), P = P_a + m^2 g_s x_{j+1} sin(Q)/(s h) (x_j - a);
- variant "factor" (133)-(135), (148)-(150): only f = 1/H^{-1} at the point (128)/(144), the weights
  1/sigma^2 and sigma integrated exactly, Q = Q_a + P/(s h) (1/a - 1/x_j) (the printed (134)/(149)
  drop the factor p_th; corrected), P = P_a + m^2 g_s sin(Q)/(2 s h) (x_j^2 - a^2);
- both: T = T_a + m/(s h) (x_j - a) ((42), (124), (133), (139), (148)).

The zeroth iterate carries no time of its own: with iterations = 0 the time is (42)/(124) on the
zeroth iterate (one extra point x_{n+1}, checked only then).

Compression half (k_c, E_ab the energy (114) of the touchdown state, p_r = -H_ab^{-1}): anchored at
touchdown as printed, a = q_r_td, x_0 = q_r_b and the printed point (123)/(132) xi = 3/4 q_r_td +
1/4 x (the chain climbs toward touchdown). The bottom leg length q_r_b is the zeroth iterate's
(Geyer et al.'s bottom, (154), or the held touchdown state's radial-work bottom); the bottom
state is (q_r_b, 0, q_th, p_th/(m q_r_b^2)) of the chain at x_0.

Decompression half (k_d, E_ba = E_ab + (k_d - k_c)/2 (l0 - q_r_b)^2 of (98), the energy jump of
the stiffness switch at the bottom, p_r = +H_ba^{-1}): anchored at that bottom, a = q_r_b, x_0 =
q_r_lo, xi = 3/4 q_r_b + 1/4 x (41)/(143). Liftoff: q_th, p_th of the chain at x_0 and p_r =
H_ba^{-1}(q_r_lo, q_th, p_th, E_ba), (45)/(142)/(151) corrected to evaluate p_r at q_r (as
printed they evaluate it at xi).

Zeroth iterate of a half: linear in u = sqrt((sigma - q_r_b)/(x_far - q_r_b)) between the bottom
(u = 0) and the far end (u = 1: touchdown, or the zeroth iterate's liftoff state), as in
:mod:`.iterative`: a map's (:func:`.iterative_helpers.zeroth_option`; Geyer et al.'s by default, with
k_c) or the held touchdown state.

Not done: the compression half anchored at the bottom (the corrected (124)-(126) of
:func:`.iterative_helpers.compression_step`, points 3/4 q_r_b + 1/4 x). There the bottom values themselves
change with every iterate (q_th_b = q_th_td - int_{q_r_b}^{q_r_td}), so the n-th iterate needs the
(n-1)-th at the points x_1 ... x_{n} of every level: n(n+1)/2 evaluations on a state that grows
with n, not a chain with a fixed loop state. The converging map :mod:`.iterative` anchors that half
at the bottom.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .. import catalog
from ..halfspec import HalfInputs, HalfSpec
from ..ir import Call, Field, Group, Guard, Iterate, Kernel, Stage, Step, Switch, sym
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..model import mechanics
from ..symbols import E, g_s, k_c, k_d, l0, m, p_th, q_r, q_rd, q_th, q_thd
from . import geyer_vs
from .iterative_helpers import (
    held_liftoff,
    radial_momentum,
    zeroth_arguments,
    zeroth_bottom,
    zeroth_liftoff,
    zeroth_option,
    zeroth_values,
)

__all__ = ["VARIANT", "ITERATIONS", "radicand", "chain_steps", "declare_maps", "declare_halves"]

VARIANT = Option(
    "variant",
    "which mean-value form each step uses",
    "integrand",
    (
        ("integrand", "the whole integrand at the point: (42)-(44), (124)-(126), (139)-(141)"),
        (
            "factor",
            "only 1/H^{-1} at the point, the weights 1/sigma^2 and sigma integrated exactly: (133)-(135), "
            "(148)-(150), with (134)/(149) keeping p_th",
        ),
    ),
    roles=("accuracy-variants", "convergence-series"),
)
BOTTOM_LENGTH = Option(
    "bottom_length",
    "the bottom leg length q_r_b the chains run to and from (section 5.2, closing estimates)",
    "zeroth",
    (
        ("zeroth", "the zeroth iterate's bottom (with Geyer's map: (154), l0 (1 + a_ab - b_ab))"),
        ("eq153", "the quartic (153) of a vertical bottom with the touchdown's energy and momentum"),
    ),
    roles=("accuracy-variants",),
)
ITERATIONS = Option(
    "iterations",
    "iterations n of each half's chain (0 = the zeroth iterate)",
    1,
    low=0,
    high=100,
    integer=True,
    roles=("accuracy-passes", "convergence-passes"),
)


def radicand(stiffness: sp.Symbol, energy: sp.Basic, x: sp.Basic, angle: sp.Basic, momentum: sp.Basic):
    """(H^{-1})^2 of (33)/(119)/(138): 2 m (E - k/2 (l0 - x)^2 - m g_s x cos q_th) - p_th^2/x^2."""
    square = radial_momentum(stiffness, E) ** 2
    return square.subs({q_r: x, q_th: angle, p_th: momentum, E: energy}, simultaneous=True)


def chain_steps(
    prefix: str,
    *,
    stiffness: sp.Symbol,
    energy: sp.Basic,
    sign: int,
    anchor: tuple[sp.Basic, sp.Basic, sp.Basic, sp.Basic],
    offset: sp.Basic,
    zeroth,
    iterations: sp.Symbol,
    variant: sp.Symbol,
) -> tuple[Step, ...]:
    """The chain of one half-stance; defines ``<prefix>e``, ``<prefix>Q``, ``<prefix>P``, ``<prefix>T``.

    ``anchor`` = (a, T_a, Q_a, P_a): the end the integrals and the mean-value points are measured
    from and the values there; ``offset`` = x_0 - a; ``zeroth(e)`` -> (q_th_0, p_th_0) at x = a + e.
    After the steps the four names hold x_0 - a and the ``iterations``-th iterate's q_th, p_th and
    time at x_0.
    """
    a, t_a, q_a, p_a = anchor

    def n(name: str) -> sp.Symbol:
        return sym(prefix + name)

    e, Q, P, T = n("e"), n("Q"), n("P"), n("T")
    e_n, e_z, rad_z = n("e_n"), n("e_z"), n("rad_z")
    q_z, p_z = zeroth(e_z)
    q_0, p_0, t_0 = n("Q0"), n("P0"), n("T0")
    start = Stage(
        (
            (e_n, offset * sp.Integer(4) ** (-iterations)),
            (e_z, e_n / 4),
            (rad_z, radicand(stiffness, energy, a + e_z, q_z, p_z)),
            *zip((q_0, p_0), zeroth(e_n), strict=True),
            # only read when iterations = 0 (then rad_z > 0); never a square root of a negative
            (t_0, sp.Piecewise((t_a + sign * m * e_n / sp.sqrt(rad_z), rad_z > 0), (t_a, True))),
        ),
        (
            Guard(
                sp.Or(iterations > 0, rad_z > 0),
                "IMAGINARY_MOMENTUM",
                "iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)",
            ),
        ),
        comment="x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0",
    )
    x, rad, h, e_new = n("x"), n("rad"), n("h"), n("e_next")
    wq, wp = n("wq"), n("wp")
    body = (
        Stage(
            ((x, a + e), (rad, radicand(stiffness, energy, x, Q, P))),
            (Guard(rad > 0, "IMAGINARY_MOMENTUM", "H^{-1} real at x_{j+1} on the current iterate"),),
        ),
        Stage(((h, sp.sqrt(rad)), (e_new, 4 * e))),
        Switch(
            variant,
            (
                (VARIANT.code("integrand"), (Stage(((wq, e_new / x**2), (wp, x * e_new))),)),
                (
                    VARIANT.code("factor"),
                    (Stage(((wq, e_new / (a * (a + e_new))), (wp, e_new * (2 * a + e_new) / 2))),),
                ),
            ),
            comment="weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)",
        ),
    )
    loop = Iterate(
        state=((e, e_n), (Q, q_0), (P, p_0), (T, t_0)),
        body=body,
        update=(
            e_new,
            q_a + sign * P * wq / h,
            p_a + sign * m**2 * g_s * sp.sin(Q) * wp / h,
            t_a + sign * m * e_new / h,
        ),
        max_iter=iterations,
        tol=sp.S.Zero,
        scales=(l0, sp.S.One, m * l0 * sp.sqrt(g_s * l0), sp.sqrt(l0 / g_s)),
        count=n("steps"),
        fail_status=None,
        comment="the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step",
    )
    return (start, loop)


@cache
def compression_kernel() -> Kernel:
    """Touchdown -> bottom (k_c) from a zeroth iterate's bottom (``z_b_*``): E_ab, the bottom leg
    length (option ``bottom_length``), the chain; ``t_bottom``, ``bottom_q_r`` ... ``bottom_q_thd``
    and ``E_ab``. One kernel for every choice of ``zeroth`` (a choice calls its zeroth map first)."""
    from ..catalog import PARAMS, TOUCHDOWN

    touchdown = tuple(a.symbol for a in TOUCHDOWN)
    q_r_td, q_rd_td, q_th_td, q_thd_td = touchdown
    p = {n: PARAMS[n].symbol for n in ("m", "l0", "k_c", "g_s")}
    q_r_b, e_ab = sym("bottom_q_r"), sym("E_ab")
    p_td = m * q_r_td**2 * q_thd_td
    at_td = {q_r: q_r_td, q_rd: q_rd_td, q_th: q_th_td, q_thd: q_thd_td}
    z_p_b = m * sym("z_b_q_r") ** 2 * sym("z_b_q_thd")

    def zeroth(e):  # anchored at touchdown, x_0 = q_r_b, points 3/4 q_r_td + 1/4 x (123)
        u = sp.sqrt(1 - e / (q_r_b - q_r_td))  # sqrt((x - q_r_b)/(q_r_td - q_r_b)), x = q_r_td + e
        return sym("z_b_q_th") + (q_th_td - sym("z_b_q_th")) * u, z_p_b + (p_td - z_p_b) * u

    quartic = geyer_vs.quartic_kernel()
    steps = (
        Stage((), (Guard(q_rd_td < 0, "TOUCHDOWN_NOT_COMPRESSING", "q_rd_td < 0"),)),
        Stage(
            ((e_ab, mechanics.stance_energy(k_c).subs(at_td, simultaneous=True)),),
            comment="E_ab (114) of the touchdown state",
        ),
        Switch(
            sym(BOTTOM_LENGTH.name),
            (
                (BOTTOM_LENGTH.code("zeroth"), (Stage(((q_r_b, sym("z_b_q_r")),)),)),
                (
                    BOTTOM_LENGTH.code("eq153"),
                    (
                        Call(
                            quartic,
                            {"p_b": p_td, "E_ab": e_ab, **p},
                            {"q_r_b": "bottom_q_r"},
                            comment="(153): the vertical bottom's quartic",
                        ),
                    ),
                ),
            ),
            comment="bottom leg length",
        ),
        Stage(
            (),
            (
                Guard(q_r_b > 0, "FALL", "bottom leg length q_r_b > 0"),
                Guard(q_r_td - q_r_b > 0, "NUMERICAL_RANGE", "bottom below touchdown"),
            ),
        ),
        *chain_steps(
            "c_",
            stiffness=k_c,
            energy=e_ab,
            sign=-1,
            anchor=(q_r_td, sp.S.Zero, q_th_td, p_td),
            offset=q_r_b - q_r_td,
            zeroth=zeroth,
            iterations=sym("iterations"),
            variant=sym("variant"),
        ),
        Stage(
            (
                (sym("t_bottom"), sym("c_T")),
                (sym("bottom_q_rd"), sp.S.Zero),
                (sym("bottom_q_th"), sym("c_Q")),
                (sym("bottom_q_thd"), sym("c_P") / (m * q_r_b**2)),
            ),
            comment="bottom state (p_r = 0)",
        ),
    )
    return Kernel(
        name="report_compression",
        summary="Schwind and Koditschek's iteration as printed, compression half from a zeroth iterate's "
        "bottom.",
        equations=tuple(str(i) for i in (*range(114, 127), *range(128, 136))) + ("154",),
        args=TOUCHDOWN
        + tuple(PARAMS[n] for n in p)
        + zeroth_arguments()[:3]
        + (VARIANT.arg(), ITERATIONS.arg(), BOTTOM_LENGTH.arg()),
        steps=steps,
        outputs=Group(
            "",
            (
                Field("t_bottom", "time from touchdown to the bottom", "s"),
                Group("bottom", catalog.POLAR, "state at the bottom (q_rd = 0)"),
                Field("E_ab", "the energy (114) of the touchdown state", "J"),
            ),
        ),
        module="iterative_report",
        check_inputs=False,
    )


def _compression_call(touchdown, p: dict) -> Call:
    """A call of :func:`compression_kernel` after :func:`~.iterative_helpers.zeroth_bottom`."""
    k = compression_kernel()
    args = {
        **dict(zip((a.name for a in catalog.TOUCHDOWN), touchdown, strict=True)),
        **{n: p[n] for n in ("m", "l0", "k_c", "g_s")},
        **{n: sym(n) for n in ("z_b_q_r", "z_b_q_th", "z_b_q_thd")},
        **{o: sym(o) for o in ("variant", "iterations", "bottom_length")},
    }
    return Call(k, args, {n: n for n in k.output_names}, comment="the compression half as printed")


def _decompression_steps(bottom, t_b, energy, guess, q_r_lo, iterations, variant) -> tuple[Step, ...]:
    """Bottom -> liftoff (k_d) with the energy E_ba: defines ``t_stance`` (from t_b) and
    ``liftoff_q_r`` ... ``liftoff_q_thd``; ``guess`` = the zeroth iterate's liftoff (q_th, q_thd)."""
    q_r_b, _, th_b, thd_b = bottom
    p_b = m * q_r_b**2 * thd_b
    p_lo = m * q_r_lo**2 * guess[1]

    def zeroth(e):  # anchored at the bottom, x_0 = q_r_lo, points 3/4 q_r_b + 1/4 x (41)/(143)
        u = sp.sqrt(e / (q_r_lo - q_r_b))
        return th_b + (guess[0] - th_b) * u, p_b + (p_lo - p_b) * u

    rad_lo = sym("rad_lo")
    return (
        Stage((), (Guard(q_r_lo - q_r_b > 0, "NO_LIFTOFF", "bottom below q_r_lo"),)),
        *chain_steps(
            "d_",
            stiffness=k_d,
            energy=energy,
            sign=1,
            anchor=(q_r_b, t_b, th_b, p_b),
            offset=q_r_lo - q_r_b,
            zeroth=zeroth,
            iterations=iterations,
            variant=variant,
        ),
        Stage(
            ((rad_lo, radicand(k_d, energy, q_r_lo, sym("d_Q"), sym("d_P"))),),
            (Guard(rad_lo > 0, "IMAGINARY_MOMENTUM", "p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real"),),
            comment="(45) corrected: p_r of the iterate at q_r_lo",
        ),
        Stage(
            (
                (sym("t_stance"), sym("d_T")),
                (sym("liftoff_q_r"), q_r_lo),
                (sym("liftoff_q_rd"), sp.sqrt(rad_lo) / m),
                (sym("liftoff_q_th"), sym("d_Q")),
                (sym("liftoff_q_thd"), sym("d_P") / (m * q_r_lo**2)),
            ),
            (Guard(sp.Abs(sym("liftoff_q_th")) < sp.pi / 2, "FALL", "the leg stays above horizontal"),),
            comment="liftoff state",
        ),
    )


@cache
def core_kernel() -> Kernel:
    """The whole stance as printed from the touchdown state and a zeroth iterate
    (:func:`~.iterative_helpers.zeroth_arguments`): the compression half, E_ba, the zeroth
    iterate's liftoff, the decompression half. One kernel for every choice of ``zeroth``."""
    from ..catalog import PARAMS, TOUCHDOWN

    touchdown = tuple(a.symbol for a in TOUCHDOWN)
    p = {n: PARAMS[n].symbol for n in ("m", "l0", "k_c", "k_d", "g_s", "q_r_lo")}
    bottom = tuple(sym(f"bottom_{q}") for q in ("q_r", "q_rd", "q_th", "q_thd"))
    e_ba = sym("E_ba")
    steps = (
        _compression_call(touchdown, p),
        Stage(
            ((e_ba, sym("E_ab") + (k_d - k_c) / 2 * (l0 - bottom[0]) ** 2),),
            comment="E_ba of (98): the energy jump of the stiffness switch",
        ),
        zeroth_liftoff(p["q_r_lo"]),
        *_decompression_steps(
            bottom,
            sym("t_bottom"),
            e_ba,
            (sym("g_lo_q_th"), sym("g_lo_q_thd")),
            p["q_r_lo"],
            sym("iterations"),
            sym("variant"),
        ),
    )
    return Kernel(
        name="report_core",
        summary="Schwind and Koditschek's iteration as printed: the stance from the touchdown state and a "
        "zeroth iterate.",
        equations=_EQUATIONS,
        args=TOUCHDOWN
        + tuple(PARAMS[n] for n in p)
        + zeroth_arguments()
        + (VARIANT.arg(), ITERATIONS.arg(), BOTTOM_LENGTH.arg()),
        steps=steps,
        outputs=catalog.STANCE,
        module="iterative_report",
        check_inputs=False,
        # numba inlines it into the stance kernel that calls it (its derivative kernel stays a call):
        # the apex-return batch 0.95x the time, its first call 4.2 s against 3.7 s (the iterative
        # map's core, inlined the same way, ran no faster: it stays a call)
        inline=True,
    )


def _build(inp: MapInputs) -> MapBuild:
    p = inp.params
    core = core_kernel()
    args = {
        **dict(zip((a.name for a in catalog.TOUCHDOWN), inp.touchdown, strict=True)),
        **{n: p[n] for n in ("m", "l0", "k_c", "k_d", "g_s", "q_r_lo")},
        **zeroth_values(),
        **{o: inp.opt(o) for o in ("variant", "iterations", "bottom_length")},
    }
    steps = (
        Stage((), (Guard(inp.touchdown[1] < 0, "TOUCHDOWN_NOT_COMPRESSING", "q_rd_td < 0"),)),
        zeroth_bottom(inp.touchdown, p, p["q_r_lo"]),
        Call(core, args, {n: n for n in core.output_names}, comment="the iteration from the zeroth iterate"),
    )
    return MapBuild(steps=steps)


def _compression_half(inp: HalfInputs) -> tuple[Step, ...]:
    """Touchdown -> bottom; the zeroth iterate's Geyer call takes q_r_lo = q_r_td (only its bottom
    is used)."""
    out = ((sym("t_half"), sym("t_bottom")),) + tuple(
        (sym(f"end_{q}"), sym(f"bottom_{q}")) for q in ("q_r", "q_rd", "q_th", "q_thd")
    )
    return (
        Stage((), (Guard(inp.state[1] < 0, "TOUCHDOWN_NOT_COMPRESSING", "q_rd_td < 0"),)),
        zeroth_bottom(inp.state, inp.params, inp.state[0]),
        _compression_call(inp.state, inp.params),
        Stage(out, comment="the bottom state"),
    )


def _decompression_half(inp: HalfInputs) -> tuple[Step, ...]:
    """From a bottom state: E_ba of (137) is that state's energy with k_d (p_r = 0 there)."""
    bottom, p = inp.state, inp.params
    q_r_b, _, q_th_b, q_thd_b = bottom
    at_b = {q_r: q_r_b, q_rd: sp.S.Zero, q_th: q_th_b, q_thd: q_thd_b}
    e_ba = sym("E_ba")
    steps = _decompression_steps(
        bottom,
        sp.S.Zero,
        e_ba,
        held_liftoff(bottom, p["q_r_lo"]),
        p["q_r_lo"],
        inp.opt("iterations"),
        inp.opt("variant"),
    )
    out = ((sym("t_half"), sym("t_stance")),) + tuple(
        (sym(f"end_{q}"), sym(f"liftoff_{q}")) for q in ("q_r", "q_rd", "q_th", "q_thd")
    )
    energy = Stage(
        ((e_ba, mechanics.stance_energy(k_d).subs(at_b, simultaneous=True)),), comment="E_ba (137)"
    )
    return (energy, *steps, Stage(out, comment="the liftoff state"))


_EQUATIONS = (
    ("27", "29", "30", "31", "32", "33", "35", "37", "38", "39", "40", "41", "42", "43", "44", "45", "98")
    + tuple(str(i) for i in range(114, 127))
    + tuple(str(i) for i in range(128, 136))
    + tuple(str(i) for i in range(137, 151) if i != 142)
    + ("154",)
)  # not (127), (136), (142), (151): p_r at xi; the liftoff p_r is (45) corrected


#: The family page of this module's maps: the iterative maps' (derive/maps/__init__.py:
#: :func:`~slipmaps.derive.maps.family_pages`).
PAGE = "iterative"


@cache
def declare_maps() -> tuple[MapSpec, ...]:
    """This module's ``MAPS``: declared once every map that can be a zeroth iterate is known (the
    choices of option ``zeroth``, :func:`~.iterative_helpers.zeroth_option`)."""
    return (
        MapSpec(
            name="iterative-report",
            title="Iterative stance map (Schwind and Koditschek, as printed)",
            section="3.2",
            equations=_EQUATIONS,
            params=("m", "l0", "k_c", "k_d", "g_s"),
            build=_build,
            options=(VARIANT, ITERATIONS, zeroth_option(), BOTTOM_LENGTH),
            as_printed=True,
            approximation_statuses=("IMAGINARY_MOMENTUM", "LIFTOFF_BACKWARD", "LIFTOFF_DOWNWARD"),
            summary="the report's iteration: n-th iterate at the end of each half from the zeroth at the "
            "n-fold mean-value point, stepping outward; compression anchored at touchdown (123), "
            "decompression at the bottom (41); bottom leg length of the zeroth iterate",
            notes="(42)-(44)/(124)-(126)/(139)-(141) or (133)-(135)/(148)-(150) with (134)/(149) keeping "
            "p_th; liftoff p_r = H^{-1} at q_r_lo ((45) corrected); E_ba of (98). IMAGINARY_MOMENTUM "
            "wherever H^{-1} of an iterate is imaginary.",
            roles=("accuracy-figure",),
        ),
    )


@cache
def declare_halves() -> tuple[HalfSpec, ...]:
    """This module's ``HALVES`` (the compression half takes option ``zeroth`` too)."""
    return (
        HalfSpec(
            name="iterative-report-compression",
            title="Iterative compression half as printed (touchdown to bottom, k_c)",
            section="5.2.1",
            equations=tuple(str(i) for i in (*range(114, 127), *range(128, 136))) + ("154",),
            whole="iterative-report",
            start="touchdown",
            params=("m", "l0", "k_c", "g_s"),
            build=_compression_half,
            options=(VARIANT, ITERATIONS, zeroth_option(), BOTTOM_LENGTH),
            summary="the compression half of `iterative-report`: the chain anchored at touchdown, the "
            "printed point (123), bottom leg length of the zeroth iterate",
        ),
        HalfSpec(
            name="iterative-report-decompression",
            title="Iterative decompression half as printed (bottom to liftoff, k_d)",
            section="5.2.2",
            equations=tuple(str(i) for i in (*range(137, 142), *range(143, 151))),
            whole="iterative-report",
            start="bottom",
            params=("m", "l0", "k_d", "g_s", "q_r_lo"),
            build=_decompression_half,
            options=(VARIANT, ITERATIONS),
            summary="the decompression half of `iterative-report` from any bottom state: E_ba the bottom "
            "state's energy with k_d, zeroth iterate the bottom's angle and angular momentum held",
        ),
    )
