"""Gravity corrections of the angular momentum (report section 4, eqs 46-77): types 0-5.

Geyer et al.'s map conserves the angular momentum p_th (Assumption 1); in stance gravity changes
it at the rate (46)-(47) tau = dp_th/dt = m g_s q_r sin q_th ((29); the report's (3) has the
wrong sign). Section 4 adds a "virtual gravity effect" P_c, an estimate of the stance impulse
int tau dt, to p_th:

- types 0-2 (4.1-4.3): the sample-mean rule (48) over 2 samples (touchdown, liftoff) or 3 (and
  the bottom), with the leg length held at l0 (49), (51), at (l0 + q_r_b)/2 (52), (54), or at the
  stance average of q_r (62), (64) from (11), (21) or (23);
- type 3 (4.4): (65), the trapezoid rule with the true leg lengths on [t_i, t_f];
- type 4 (4.5): (76), type 2's rule with the average leg length on [t_i, t_f];
- type 5 (4.6, unfinished in the report): designed here (docs/type5.md): a time-varying momentum.

How P_c enters is left open by (50): "p_th + P_c, the rest stays the same". Two readings are
declared (option ``reading``): ``report`` puts p_th + P_c everywhere in Geyer's formulas (its
liftoff radial speed is Geyer's closed form); ``mean`` runs the trajectory (radial solution and
leg angle) with the stance-mean momentum p_th + P_c/2, which is what the constant torque of (48)
gives, P(t) = p_th + P_c t/t_s, takes the rates from the momentum at that instant and the liftoff
radial speed from the exact energy (27) (the SLIP conserves energy, the approximations do not).
P_c depends on the liftoff state it corrects: ``iterations`` passes of P_c <- P_c(map(P_c)) from
P_c = 0 (Geyer's map), stopping early when P_c moves by less than ``tol`` times a momentum scale
(``tol = 0``: exactly ``iterations`` passes).

Every formula below is derived here (SymPy) from the model and from Geyer's derivation; the
registry (:mod:`slipmaps.derive.equations.sec4`) compares the printed equations with them.

A family module: it declares the family :data:`FAMILY` (its options and module) and its members,
the maps ``gravity-type0`` ... ``gravity-type4`` (:data:`MAPS`, ``MapSpec.family``), each fixing
the options its rule does not read. The types differ only in the impulse rule, a kernel of its
own per type (:func:`impulse_kernel`), so their kernels in ``generated/gravity.py`` are one body
(derive/share.py) that each type's entry points call with its rule. Type 5, a design of its own, is
declared in :mod:`.gravity_type5` (which builds on this module's torque and energy).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .. import catalog
from ..ir import Arg, Call, Field, Group, Guard, Iterate, Kernel, Stage, Step, Switch, sym
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..model import mechanics
from ..outline import defined, used
from ..symbols import (
    a,
    b,
    g_s,
    k,
    l0,
    m,
    omega0_hat,
    q_r,
    q_r_lo,
    q_r_td,
    q_rd,
    q_rd_td,
    q_th,
    q_th_td,
    q_thd,
    q_thd_td,
    t,
)
from . import geyer

T_I, T_F = sym("t_i"), sym("t_f")
E_SYM, P_SYM = sym("E"), sym("p")


# --------------------------------------------------------------------------------------------
# Derivation: the torque, the sample-mean impulse, the average leg lengths, the liftoff speed.


@cache
def torque() -> sp.Basic:
    """Eq (47): tau = dp_th/dt, the fourth row of Hamilton's equations (29) of the Hamiltonian (27)."""
    return mechanics.hamiltonian_vector_field()[3]


def impulse(duration, samples) -> sp.Basic:
    """Eq (48): P_c = (t - t0) times the mean of the torque (47) at the samples (q_r_i, q_th_i)."""
    tau = torque()
    return duration * sum(tau.subs({q_r: r, q_th: th}) for r, th in samples) / len(samples)


def held_leg_length(kind: int, q_r_b: sp.Basic, stance_average: sp.Basic) -> sp.Basic:
    """The leg length the torque of types 0-2 is taken at: l0 (49), (l0 + q_r_b)/2 (52), the
    stance-average leg length ``stance_average`` (62)."""
    return (l0, (l0 + q_r_b) / 2, stance_average)[kind]


def half_impulses(t_b, t_s, angles, lengths) -> tuple[sp.Basic, sp.Basic]:
    """(48) on [t_td, t_b] and [t_b, t_lo]: each half's impulse from the torque at its two ends, the
    angles (q_th_td, q_th_b, q_th_lo) with the leg lengths ``lengths`` (touchdown, bottom, bottom,
    liftoff): the true ones for (65), each half's average (L1, L1, L2, L2) for (76), one held
    length (types 0-2, :func:`held_leg_length`) for each half's form of (49), (52), (62)."""
    (th_td, th_b, th_lo), (r_td, r_b1, r_b2, r_lo) = angles, lengths
    return impulse(t_b, [(r_td, th_td), (r_b1, th_b)]), impulse(t_s - t_b, [(r_b2, th_b), (r_lo, th_lo)])


def half_impulse_switch(
    inp: MapInputs, prefix: str, times: tuple, angles: tuple, lengths: tuple, averages: tuple, source: str
) -> Switch:
    """``<prefix>P_new1``, ``<prefix>P_new2``: each half's stance impulse by option ``gravity`` of a map
    split at the bottom (``geyer-vs``, ``geyer-damped``), one branch per choice the option declares:
    (48) on [t_td, t_b] and [t_b, t_lo] from the torque at each half's two ends, with the leg length
    of the type: ``type0`` l0 (as (49)), ``type1`` (l0 + q_r_b)/2 (as (52)), ``type2`` the stance
    average of ``source`` (as (62)), ``type3`` the true leg lengths ``lengths`` (q_r_td, q_r_b, q_r_b,
    q_r_lo): (65); ``type4`` each half's average ``averages`` (two expressions of ``source``): (76);
    ``none`` no effect. ``times``: (t_b, t_s); ``angles``: (q_th_td, q_th_b, q_th_lo)."""
    (t_b, t_s), choice = times, inp.options["gravity"]
    P1, P2 = sym(f"{prefix}P_new1"), sym(f"{prefix}P_new2")
    L1, L2, L = sym(f"_{prefix}L1"), sym(f"_{prefix}L2"), sym(f"_{prefix}L")  # private to their branch
    q_r_b = lengths[1]

    def rule(held: tuple, comment: str, defs: tuple = ()) -> tuple[Step, ...]:
        impulses = half_impulses(t_b, t_s, angles, held)
        return (Stage((*defs, *zip((P1, P2), impulses, strict=True)), comment=comment),)

    averages_defs = ((L1, averages[0]), (L2, averages[1]))
    rules = {
        "none": lambda: (Stage(((P1, sp.S.Zero), (P2, sp.S.Zero))),),
        "type0": lambda: rule((held_leg_length(0, q_r_b, L),) * 4, "eq (48) on each half at l0, as (49)"),
        "type1": lambda: rule(
            (held_leg_length(1, q_r_b, L),) * 4, "eq (48) on each half at (l0 + q_r_b)/2, as (52)"
        ),
        "type2": lambda: rule(
            (held_leg_length(2, q_r_b, L),) * 4,
            f"eq (48) on each half at the stance-average leg length of {source}, as (62)",
            (*averages_defs, (L, (t_b * L1 + (t_s - t_b) * L2) / t_s)),
        ),
        "type3": lambda: rule(lengths, "eq (65) on each half"),
        "type4": lambda: rule(
            (L1, L1, L2, L2), f"eq (76) on each half, the average leg length of {source} on it", averages_defs
        ),
    }
    return Switch(
        inp.opt("gravity"),
        tuple((choice.code(v), rules[v]()) for v in choice.values),
        comment="the virtual gravity effect of each half",
    )


#: The extra outputs of a map with :func:`half_fixed_point`: each half's virtual gravity effect and
#: the passes run.
HALF_EXTRAS = (
    Field(
        "P_c_compression", "virtual gravity effect of the first half (0 unless gravity)", "N m s", odd=True
    ),
    Field("P_c_decompression", "virtual gravity effect of the second half", "N m s", odd=True),
    Field("passes", "fixed-point passes run (0 unless gravity)", ""),
)


def half_fixed_point(inp: MapInputs, prefix: str, evaluate: tuple, body: Switch) -> tuple[Step, ...]:
    """The fixed point of the two halves' virtual gravity effects ``P_c_compression``,
    ``P_c_decompression`` from 0 (option ``gravity`` none: no pass), ``evaluate`` the pass named by
    ``prefix`` at every iterate, ``body`` its impulses (:func:`half_impulse_switch`); then the stance
    outputs from the pass at the final iterate."""
    P1, P2 = sym("P_c_compression"), sym("P_c_decompression")
    return (
        Iterate(
            state=((P1, sp.S.Zero), (P2, sp.S.Zero)),
            # one pass at every iterate, the final one included (visible after the loop)
            evaluate=evaluate,
            body=(body,),
            update=(sym(f"{prefix}P_new1"), sym(f"{prefix}P_new2")),
            max_iter=sp.Piecewise((0, inp.options["gravity"].is_("none")), (inp.opt("iterations"), True)),
            tol=inp.opt("tol"),
            scales=(MOMENTUM_SCALE, MOMENTUM_SCALE),
            count=sym("passes"),
            fail_status="NOT_CONVERGED",
            comment="fixed point of the two halves' virtual gravity effects, from 0 (none: no pass)",
            # no pass by default: the direction array would cost the Jacobian 7-12 % (measured)
            per_direction=False,
        ),
        Stage(
            tuple((sym(f.name), sym(prefix + f.name)) for f in catalog.STANCE.fields()),
            comment="the stance outputs: the pass at the final iterate",
        ),
    )


@cache
def stance_radius(source: str) -> sp.Basic:
    """q_r(t) of the stance from which an average leg length is taken.

    ``eq11``: (11), t the absolute time of (11); ``eq21``: (21), t from touchdown; ``eq23``: (23),
    t from touchdown, written with omega0_hat (omega0_hat^2 = k/m + 3 q_thd_td^2 at q_r_td = l0).
    """
    if source == "eq11":
        return l0 * (1 + geyer.radial_solution(t))
    if source == "eq21":
        return geyer.touchdown_shifted_solution()[0]
    if source == "eq23":
        w = sp.Symbol("omega0_hat", positive=True)
        radius = geyer.touchdown_state_solution()[0].subs(k, m * (w**2 - 3 * q_thd_td**2))
        # |q_rd_td| = -q_rd_td: the stance starts compressing (guarded by TOUCHDOWN_NOT_COMPRESSING)
        return sp.simplify(radius.subs(sp.Abs(q_rd_td), -q_rd_td)).subs(w, omega0_hat)
    raise ValueError(f"unknown leg-length source {source!r}")


@cache
def average_leg_length(source: str) -> sp.Basic:
    """Eqs (55)-(61), (67)-(75): q_r_av(t_i, t_f) = int_{t_i}^{t_f} q_r dt / (t_f - t_i), by SymPy."""
    radius = stance_radius(source)
    return sp.simplify(sp.integrate(radius, (t, T_I, T_F)) / (T_F - T_I))


@cache
def liftoff_radial_speed(stiffness: sp.Symbol = k) -> sp.Basic:
    """q_rd >= 0 at (q_r, q_th) with angular momentum p on the energy level E of (27) (leg stiffness
    ``stiffness``: k_d after a stiffness switch).

    Returns q_rd^2 from H(q_r, q_th, m q_rd, p) = E; the extending root is its positive square root.
    """
    energy = mechanics.stance_energy(stiffness).subs(q_thd, P_SYM / (m * q_r**2))
    # (27) is m q_rd^2 / 2 plus a q_rd-free rest, so H = E has the roots +-sqrt(2 (E - rest) / m).
    rest = energy.subs(q_rd, 0)
    if sp.simplify(energy - rest - m * q_rd**2 / 2) != 0:
        raise AssertionError("the stance energy (27) is not m q_rd^2/2 plus a q_rd-free part")
    return sp.expand(2 * (E_SYM - rest) / m)


# --------------------------------------------------------------------------------------------
# Declaration helpers shared by types 0-4.

_READING = Option(
    "reading",
    "how P_c enters Geyer's formulas, eq (50)",
    "mean",
    choices=(
        (
            "mean",
            "trajectory with the stance-mean momentum p_th + P_c/2 (constant torque of (48)), "
            "rates from the momentum at that instant, liftoff radial speed from the exact energy (27)",
        ),
        ("report", "p_th + P_c everywhere in Geyer's formulas, liftoff radial speed from Geyer's (11)"),
    ),
    roles=("accuracy-readings",),
)
_SAMPLES = Option(
    "samples",
    "number of torque samples in (48): 2 (touchdown, liftoff) or 3 (and the bottom)",
    2,
    low=2,
    high=3,
    integer=True,
    roles=("accuracy-variants",),
)
_LEG_LENGTH = Option(
    "leg_length",
    "the stance solution the average leg length is taken from",
    "eq11",
    choices=(
        ("eq11", "(11), eqs (55)-(57) and (67)-(68) (their printed forms lack an l0 on the b term)"),
        ("eq21", "(21), eqs (58)-(59) and (70)-(72); touchdown at l0 only"),
        ("eq23", "(23), eqs (60)-(61) and (73)-(75); touchdown at l0 only"),
    ),
    at_rest_length=("eq21", "eq23"),
    roles=("accuracy-variants",),
)
_INTERVAL = Option(
    "interval",
    "the intervals [t_i, t_f] of the correction",
    "halves",
    choices=(
        ("stance", "one interval, touchdown to liftoff"),
        (
            "halves",
            "touchdown to bottom and bottom to liftoff, summed (the report's suggestion for "
            "the split maps of section 5)",
        ),
    ),
    roles=("accuracy-variants",),
)


def iterations_option(default: int, roles: tuple[str, ...] = ("accuracy-passes",)) -> Option:
    """The pass count of P_c; ``roles``: which studies vary it (the accuracy study, one pass and the
    fixed point, by default)."""
    return Option(
        "iterations",
        "passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map)",
        default,
        low=0,
        high=1000,
        integer=True,
        roles=roles,
    )


def tol_option(default: float) -> Option:
    return Option(
        "tol",
        "stop when P_c moves by at most tol times the momentum scale; 0: run all passes",
        default,
        low=0.0,
        high=1.0,
        roles=("tolerance",),
    )


_EXTRAS = (
    Field("P_c", "virtual gravity effect: the stance impulse added to p_th", "N m s", odd=True),
    Field("passes", "fixed-point passes run", ""),
)
MOMENTUM_SCALE = sp.Abs(sym("p_td")) + m * l0 * sp.sqrt(g_s * l0)


def _n(prefix: str, name: str) -> sp.Symbol:
    return sym(prefix + name)


def _trajectory(prefix: str, p_traj: sp.Basic) -> tuple[Step, ...]:
    """Geyer's map run with the trajectory momentum ``p_traj`` (as an effective touchdown rate)."""
    return (
        Stage(((_n(prefix, "q_thd_eff"), p_traj / (m * q_r_td**2)),), comment="effective touchdown rate"),
        *geyer.stance_steps(_n(prefix, "q_thd_eff"), prefix),
    )


def _average(source: str, prefix: str, t_from: sp.Basic, t_to: sp.Basic) -> sp.Basic:
    """The average leg length of ``source`` on [t_from, t_to] (times from touchdown) in kernel names."""
    expr = average_leg_length(source)
    names = {
        a: _n(prefix, "a"),
        b: _n(prefix, "b"),
        omega0_hat: _n(prefix, "omega0_hat"),
        q_thd_td: _n(prefix, "q_thd_eff"),
    }
    if source == "eq11":  # (11) runs on the absolute time: touchdown at phase_td / omega0_hat
        shift = _n(prefix, "phase_td") / _n(prefix, "omega0_hat")
        return expr.subs({T_I: t_from + shift, T_F: t_to + shift}).subs(names)
    return expr.subs({T_I: t_from, T_F: t_to}).subs(names)


def _angles(prefix: str):
    return q_th_td, _n(prefix, "bottom_q_th"), _n(prefix, "liftoff_q_th")


def _impulse_steps(kind: int, inp: MapInputs, prefix: str) -> tuple[Step, ...]:
    """Steps defining ``<prefix>P_new``, the stance impulse of the trajectory named by ``prefix``."""
    th_td, th_b, th_lo = _angles(prefix)
    t_b, t_s = _n(prefix, "t_bottom"), _n(prefix, "t_stance")
    q_r_b = _n(prefix, "bottom_q_r")
    P_new, L = _n(prefix, "P_new"), sym(f"_{prefix}L")  # L: private to its branch

    def ramp(total):
        return Stage(((P_new, total),))

    def by_samples(length: sp.Basic) -> Switch:
        return Switch(
            inp.opt("samples"),
            (
                (2, (ramp(impulse(t_s, [(length, th_td), (length, th_lo)])),)),
                (3, (ramp(impulse(t_s, [(length, th_td), (length, th_b), (length, th_lo)])),)),
            ),
            comment="eq (48) with 2 or 3 samples",
        )

    def by_leg_length(t_from, t_to, name) -> Switch:
        cases = tuple(
            (i, (Stage(((name, _average(src, prefix, t_from, t_to)),)),))
            for i, src in enumerate(inp.options["leg_length"].values)
        )
        return Switch(inp.opt("leg_length"), cases, comment="average leg length, eqs (55)-(61) / (67)-(75)")

    if kind in (0, 1):
        return (by_samples(held_leg_length(kind, q_r_b, L)),)
    if kind == 2:
        return (by_leg_length(0, t_s, L), by_samples(held_leg_length(kind, q_r_b, L)))
    halves = inp.options["interval"].code("halves")
    whole = inp.options["interval"].code("stance")
    if kind == 3:  # (65) on [t_td, t_lo] or on [t_td, t_b] + [t_b, t_lo]
        first, second = half_impulses(t_b, t_s, (th_td, th_b, th_lo), (q_r_td, q_r_b, q_r_b, q_r_lo))
        return (
            Switch(
                inp.opt("interval"),
                (
                    (whole, (ramp(impulse(t_s, [(q_r_td, th_td), (q_r_lo, th_lo)])),)),
                    (halves, (Stage(((P_new, first + second),)),)),
                ),
                comment="eq (65)",
            ),
        )
    # kind == 4: (76) with the average leg length of each interval
    L1, L2 = sym(f"_{prefix}L1"), sym(f"_{prefix}L2")  # private to their branch
    return (
        Switch(
            inp.opt("interval"),
            (
                (
                    whole,
                    (
                        by_leg_length(0, t_s, sym(f"_{prefix}L")),
                        ramp(impulse(t_s, [(sym(f"_{prefix}L"), th_td), (sym(f"_{prefix}L"), th_lo)])),
                    ),
                ),
                (
                    halves,
                    (
                        by_leg_length(0, t_b, L1),
                        by_leg_length(t_b, t_s, L2),
                        Stage(
                            (
                                (
                                    P_new,
                                    sum(half_impulses(t_b, t_s, (th_td, th_b, th_lo), (L1, L1, L2, L2))),
                                ),
                            )
                        ),
                    ),
                ),
            ),
            comment="eq (76)",
        ),
    )


def touchdown_invariants(stiffness: sp.Symbol = k) -> Stage:
    """``p_td`` and ``E_td``: the angular momentum and the total energy (27) of the touchdown state
    (with the leg stiffness ``stiffness``)."""
    at_td = {q_r: q_r_td, q_rd: q_rd_td, q_th: q_th_td, q_thd: q_thd_td}
    return Stage(
        (
            (sym("p_td"), m * q_r_td**2 * q_thd_td),
            (sym("E_td"), mechanics.stance_energy(stiffness).subs(at_td)),
        ),
        comment="angular momentum and total energy (27) at touchdown",
    )


def liftoff_speed_from_energy(angle: sp.Basic, momentum: sp.Basic) -> tuple[Step, ...]:
    """``liftoff_q_rd`` on the touchdown's energy level E_td at (q_r_lo, ``angle``, ``momentum``);
    status ENERGY_DEFICIT where the approximate liftoff state needs more energy than there is."""
    radicand = liftoff_radial_speed()
    at_lo = {q_r: q_r_lo, q_th: angle, P_SYM: momentum, E_SYM: sym("E_td")}
    square = sym("_q_rd_lo_sq")
    return (
        Stage(
            ((square, radicand.subs(at_lo)),),
            (Guard(square >= 0, "ENERGY_DEFICIT", "q_rd_lo^2 from the energy (27)"),),
        ),
        Stage(((sym("liftoff_q_rd"), sp.sqrt(square)),), comment="q_rd_lo from the energy"),
    )


@cache
def _impulse_reads() -> tuple[str, ...]:
    """What the types' impulse rules read (the trajectory of the current iterate, by its kernel
    names, the parameters and the options): the arguments of every type's impulse kernel, the same
    for all. The family's stance arguments first, in their order, then the trajectory's names."""
    inp = FAMILY.inputs(catalog.TOUCHDOWN, FAMILY.params + ("q_r_lo",))
    names: set[str] = set()
    for kind in range(5):
        steps = _impulse_steps(kind, inp, "i_")
        names |= used(steps) - defined(steps)
    first = [a.name for a in FAMILY.stance_args() if a.name in names]
    return tuple(first + sorted(names - set(first)))


@cache
def impulse_kernel(kind: int) -> Kernel:
    """Type ``kind``'s impulse rule of P_c as a kernel of its own (inlined): the one step in which
    the types differ, so that their stance kernels differ only in the kernel they call and
    derive/share.py renders them as one body."""
    inp = FAMILY.inputs(catalog.TOUCHDOWN, FAMILY.params + ("q_r_lo",))
    docs = {a.name: a for a in FAMILY.stance_args()}
    args = tuple(
        docs.get(n) or Arg(sym(n), f"{n} of the current iterate's trajectory") for n in _impulse_reads()
    )
    return Kernel(
        name=f"gravity_impulse_type{kind}",
        summary=f"Type {kind}'s stance impulse P_c of the trajectory (report section 4.{kind + 1}).",
        equations=tuple(e for e in MAPS[kind].equations if e not in _COMMON_EQS),
        args=args,
        steps=_impulse_steps(kind, inp, "i_"),
        outputs=Group("", (Field("i_P_new", "the stance impulse of the trajectory", "N m s"),)),
        check_inputs=False,
        module="gravity",
        inline=True,
        # its callers read all of its derivatives: every type's kernels the same code
        dense_tangent=True,
    )


def _constant_correction(kind: int):
    """The build function of type ``kind`` (0-4): Geyer's map with a constant virtual gravity effect,
    its impulse by the type's rule (:func:`impulse_kernel`)."""

    def build(inp: MapInputs) -> MapBuild:
        p_td, P_c, share, ramp = sym("p_td"), sym("P_c"), sym("share"), sym("ramp")
        reading = inp.options["reading"]

        def momentum(time, t_s):
            """The angular momentum a time t after touchdown: p_td + P_c t / t_s under (48)'s constant
            torque (``mean``), p_td + P_c throughout (``report``)."""
            return p_td + P_c * (ramp * time / t_s + (1 - ramp))

        setup: tuple[Step, ...] = (
            touchdown_invariants(),
            Switch(
                inp.opt("reading"),
                (
                    (reading.code("mean"), (Stage(((share, sp.Rational(1, 2)), (ramp, sp.S.One))),)),
                    (reading.code("report"), (Stage(((share, sp.S.One), (ramp, sp.S.Zero))),)),
                ),
                comment="trajectory momentum p_td + share P_c: the stance mean (P_c/2) or the report's",
            ),
            Iterate(
                state=((P_c, sp.S.Zero),),
                # the trajectory at every iterate, the final one included (visible after the loop)
                evaluate=_trajectory("i_", p_td + share * P_c),
                body=(
                    Call(
                        impulse_kernel(kind),
                        {n: sym(n) for n in _impulse_reads()},
                        {"i_P_new": "i_P_new"},
                        comment="the type's impulse rule",
                    ),
                ),
                update=(sym("i_P_new"),),
                max_iter=inp.opt("iterations"),
                tol=inp.opt("tol"),
                scales=(MOMENTUM_SCALE,),
                count=sym("passes"),
                comment="fixed point of the virtual gravity effect, from P_c = 0 (Geyer's map)",
            ),
        )
        f_t_b, f_t_s = sym("i_t_bottom"), sym("i_t_stance")
        outputs = (
            Stage(
                (
                    (sym("t_bottom"), f_t_b),
                    (sym("t_stance"), f_t_s),
                    (sym("bottom_q_r"), sym("i_bottom_q_r")),
                    (sym("bottom_q_rd"), sp.S.Zero),
                    (sym("bottom_q_th"), sym("i_bottom_q_th")),
                    (sym("bottom_q_thd"), momentum(f_t_b, f_t_s) / (m * sym("i_bottom_q_r") ** 2)),
                    (sym("liftoff_q_r"), q_r_lo),
                    (sym("liftoff_q_th"), sym("i_liftoff_q_th")),
                    (sym("liftoff_q_thd"), (p_td + P_c) / (m * q_r_lo**2)),
                ),
                comment="the rates from the momentum at that instant; p_td + P_c at liftoff, eq (50)",
            ),
            Switch(
                inp.opt("reading"),
                (
                    (
                        reading.code("mean"),
                        liftoff_speed_from_energy(sym("i_liftoff_q_th"), p_td + P_c),
                    ),
                    (
                        reading.code("report"),
                        (Stage(((sym("liftoff_q_rd"), sym("i_liftoff_q_rd")),), comment="from (11)"),),
                    ),
                ),
            ),
        )

        def state_at(time: sp.Symbol) -> tuple[Step, ...]:
            st = geyer.state_kernel()
            f = {x: sym("i_" + x) for x in ("omega", "omega0_hat", "a", "b", "phase_td")}
            return setup + (
                Stage(((sym("phase_t"), f["phase_td"] + f["omega0_hat"] * time),)),
                Call(
                    st,
                    {"phase": sym("phase_t"), "q_th_td": q_th_td, "l0": l0, **f},
                    {"q_r": "q_r", "q_rd": "q_rd", "q_th": "q_th"},
                ),
                Stage(
                    ((sym("q_thd"), momentum(time, f_t_s) / (m * sym("q_r") ** 2)),),
                    comment="the momentum at t",
                ),
            )

        return MapBuild(steps=setup + outputs, state_at=state_at)

    return build


_COMMON_EQS = ("46", "47", "48", "50")
_NOTES = (
    "Geyer et al.'s map (3.1) run with a corrected angular momentum; see the module docstring of "
    "derive/maps/gravity.py and docs/gravity.md for the two readings of (50)."
)
_PARAMS, _REQUIRES = ("m", "l0", "k", "g_s"), ("constant_stiffness",)


def _family_build(inp: MapInputs) -> MapBuild:
    """The family's build: none (each type builds with its own rule, :func:`_constant_correction`);
    its module is the family's derivation module, named in the generated headers."""
    raise ValueError("the gravity family is built by its types (gravity-type0 ... gravity-type4)")


#: The family of types 0-4: the options every type's kernels take and their module; each type is a
#: member map (:data:`MAPS`) that fixes the options its rule does not read.
FAMILY = MapSpec(
    name="gravity",
    title="Gravity corrections types 0-4",
    section="4.1-4.5",
    equations=tuple(str(e) for e in range(46, 78)),
    params=_PARAMS,
    requires=_REQUIRES,
    build=_family_build,
    options=(
        _READING,
        _SAMPLES,
        _INTERVAL,
        _LEG_LENGTH,
        iterations_option(100),
        tol_option(1e-12),
    ),
    extras=_EXTRAS,
    summary="P_c by the impulse rule of its type (the member maps gravity-type0 ... gravity-type4)",
    notes=_NOTES,
)
#: The value a member fixes an option its rule does not read to (any valid one).
_UNREAD = {"samples": 2, "leg_length": "eq11", "interval": "halves"}


def _spec(
    kind: int,
    title: str,
    eqs: tuple[str, ...],
    options: tuple[Option, ...],
    summary: str,
    roles: tuple[str, ...] = (),
) -> MapSpec:
    public = {o.name for o in options}
    return MapSpec(
        name=f"gravity-type{kind}",
        title=title,
        section=f"4.{kind + 1}",
        equations=tuple(sorted(_COMMON_EQS + eqs, key=int)),
        params=_PARAMS,
        requires=_REQUIRES,
        build=_constant_correction(kind),
        options=options,
        extras=_EXTRAS,
        summary=summary,
        notes=_NOTES,
        roles=("yu-target",) + roles,
        family=FAMILY,
        fixed=tuple((n, v) for n, v in _UNREAD.items() if n not in public),
    )


MAPS = (
    _spec(
        0,
        "Gravity correction type 0 (leg length l0)",
        ("49", "51"),
        (_READING, _SAMPLES, iterations_option(1), tol_option(0.0)),
        "P_c from the torque at l0 sampled at touchdown and liftoff (49) or also the bottom (51)",
    ),
    _spec(
        1,
        "Gravity correction type 1 (leg length (l0 + q_r_b)/2)",
        ("52", "53", "54"),
        (_READING, _SAMPLES, iterations_option(100), tol_option(1e-12)),
        "P_c from the torque at the mean of the rest and bottom leg lengths (52), (54)",
    ),
    _spec(
        2,
        "Gravity correction type 2 (average leg length)",
        ("55", "56", "57", "58", "59", "60", "61", "62", "63", "64"),
        (_READING, _SAMPLES, _LEG_LENGTH, iterations_option(100), tol_option(1e-12)),
        "P_c from the torque at the stance-average leg length (62), (64)",
        roles=("accuracy-figure",),
    ),
    _spec(
        3,
        "Gravity correction type 3 (trapezoid on [t_i, t_f])",
        ("65", "66"),
        (_READING, _INTERVAL, iterations_option(100), tol_option(1e-12)),
        "P_c by the trapezoid rule on the torque with the true leg lengths (65), whole stance or halves",
    ),
    _spec(
        4,
        "Gravity correction type 4 (average leg length on [t_i, t_f])",
        ("67", "68", "69", "70", "71", "72", "73", "74", "75", "76", "77"),
        (_READING, _INTERVAL, _LEG_LENGTH, iterations_option(100), tol_option(1e-12)),
        "P_c from the torque at the average leg length of each interval (76), whole stance or halves",
    ),
)
