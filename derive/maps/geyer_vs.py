"""The simple variable-stiffness stance map (report section 5.1, eqs 78-113): Geyer et al.'s map
split at the bottom, k_c while compressing, k_d after.

Apex to bottom (78)-(89) is Geyer's solution (11) with omega0^2 = k_c/m from the touchdown state,
up to its bottom phase 3 pi/2 (81). At the bottom the stiffness changes: the spring energy jumps by
(97) E_additional = (k_d - k_c)(l0 - q_r_b)^2/2, so E_ba = E_ab + E_additional (98), and bottom to
apex (90)-(105) is again (11), now with omega0^2 = k_d/m and epsilon_ba = 2 E_ba/(m l0^2) (99),
the same omega (100) (Remark 2: p_th is continuous at the bottom), from the bottom phase to the
liftoff phase of (94).

What E_ab is decides whether q_r is continuous at the bottom. Option ``continuity``:

- ``report``: E_ab the touchdown's total energy (27), as the report says, and a_ba, b_ba by
  (103)-(104). The first half conserves Geyer's approximate energy (8) instead (small angle and
  Taylor polynomial), so l0 (1 + a_ba - b_ba) misses the bottom leg length l0 (1 + a_ab - b_ab):
  the jump of the report's Figure 7 (middle).
- ``constrained``: the same b_ba (104), a_ba from the continuity constraint (111) a_ba = a_ab -
  b_ab + b_ba, which (108)-(109) give at the bottom phases (81), (93) (:func:`continuity_constraint`).
  The second half is then no longer a solution of its own radial quadratic (9) (the report's
  "invariant under a small shift").
- ``energy``: E_ab the energy the first half conserves (Geyer's (8) at touchdown, as in
  :func:`.geyer.touchdown_parameters`). Then (98) makes the bottom leg length a root of the second
  half's quadratic (:func:`consistent_bottom_is_a_root`): (103)-(104) are continuous with no
  constraint, (110) holds by itself. (With a gravity correction, (8) is taken at the bottom with
  the second half's omega_ba.) When the bottom is the upper root (a soft k_d: the k_d spring cannot
  start extending the leg), the map returns RECOMPRESSION, as the exact simulator does; a leg that
  extends but cannot reach q_r_lo is NO_LIFTOFF here, RECOMPRESSION there (it turns back).

The bottom leg length estimates of section 5.2 are here too: the quartic (153) of a symmetric
(vertical) bottom, whose first printed line (152) lacks the square of p_th (:func:`bottom_quartic`),
and (154) = Geyer's bottom l0 (1 + a_ab - b_ab).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .. import catalog
from ..ir import Arg, Call, Field, Group, Guard, Iterate, Kernel, Stage, Step, Switch, sym
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..model import mechanics
from ..symbols import (
    E,
    a,
    b,
    epsilon,
    g_s,
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
    q_rd,
    q_th,
    q_th_td,
    q_thd,
    rho,
    rho_d,
)
from . import geyer
from .gravity import (
    E_SYM,
    HALF_EXTRAS,
    P_SYM,
    T_F,
    T_I,
    average_leg_length,
    half_fixed_point,
    half_impulse_switch,
    iterations_option,
    liftoff_radial_speed,
    tol_option,
    touchdown_invariants,
)

__all__ = [
    "half_solution",
    "energy_jump",
    "continuity_constraint",
    "consistent_bottom_is_a_root",
    "second_state",
    "bottom_quartic",
    "quartic_kernel",
    "MAPS",
]

BOTTOM_PHASE = 3 * sp.pi / 2  # (81), (93) with n = 0


# --------------------------------------------------------------------------------------------
# Derivation


@cache
def half_solution(stiffness: sp.Symbol) -> dict[str, sp.Basic]:
    """(84)-(87) / (101)-(105): omega0_hat, a, b^2 of (11) with omega0^2 = stiffness/m, in epsilon
    and omega (Geyer's (9)-(11) with the half's stiffness)."""
    sol = geyer.radial_solution_parameters()
    sub = {omega0: sp.sqrt(stiffness / m)}
    return {key: sp.simplify(sol[key].subs(sub)) for key in ("omega0_hat", "a", "b2")}


@cache
def energy_jump() -> sp.Basic:
    """(97): the total energy (27) just after the bottom (k_d) minus just before (k_c), same state."""
    return sp.factor(mechanics.stance_energy(k_d) - mechanics.stance_energy(k_c))


@cache
def continuity_constraint() -> sp.Basic:
    """(110) solved for a_ba, i.e. (111): q_r (108) and q_thd (109) continuous at the bottom phases
    3 pi/2 of (81) and (93). Returns a_ba in a_ab, b_ab, b_ba."""
    a_ab, b_ab, a_ba, b_ba = sp.symbols("a_ab b_ab a_ba b_ba", real=True)
    s = sp.sin(BOTTOM_PHASE)
    radius = sp.Eq(l0 * (1 + a_ab + b_ab * s), l0 * (1 + a_ba + b_ba * s))
    rate = sp.Eq(omega * (1 - 2 * a_ab - 2 * b_ab * s), omega * (1 - 2 * a_ba - 2 * b_ba * s))
    (solution,) = sp.solve([radius, rate], [a_ba], dict=True)
    return solution[a_ba]


@cache
def consistent_bottom_is_a_root() -> sp.Basic:
    """With epsilon_ba = epsilon_ab + (k_d - k_c)/m rho_b^2 ((98) in the units of (82)), the bottom
    rho_b = a_ab - b_ab of the first half's quadratic (9) is a root of the second half's: returns
    the second quadratic at rho_b minus the first one there, identically zero (so the second is zero
    where the first is)."""
    lam_, mu_, nu_ = geyer.radial_quadratic()
    rho_b, eps_ab = sp.symbols("rho_b epsilon_ab", real=True)
    first = (lam_ * rho_b**2 + mu_ * rho_b + nu_).subs({omega0: sp.sqrt(k_c / m), epsilon: eps_ab})
    eps_ba = eps_ab + (k_d - k_c) / m * rho_b**2
    second = (lam_ * rho_b**2 + mu_ * rho_b + nu_).subs({omega0: sp.sqrt(k_d / m), epsilon: eps_ba})
    return sp.expand(second - first)


@cache
def bottom_quartic() -> sp.Basic:
    """(153): q_r^2 (H - E_ab) at a vertical bottom (q_rd = 0, q_th = 0) of the energy (27) with
    k_c and angular momentum p_th, a quartic in q_r."""
    energy = mechanics.stance_energy(k_c).subs({q_rd: 0, q_th: 0, q_thd: p_th / (m * q_r**2)})
    return sp.expand(q_r**2 * (energy - E))


# --------------------------------------------------------------------------------------------
# Kernels

_Q = sym("qb")
QUARTIC_PASSES = 60


@cache
def quartic_kernel() -> Kernel:
    """The bottom leg length of (153): the root of V(q) = E in (0, l0] on the compressing side,
    V(q) = p_th^2/(2 m q^2) + k_c (l0 - q)^2/2 + m g_s q the vertical effective potential.

    V is convex on q > 0 and grows without bound at 0 (p_th != 0), so the quartic q^2 (V - E) has at
    most two positive roots; the bottom is the smaller one. Newton's method on V - E from a point
    left of it climbs to it monotonically (the tangent of a convex function stays below it); the
    start is the larger of two points where V >= E: the smaller root of the spring-and-gravity part
    alone and |p_th| / sqrt(2 m (E - its minimum)). A root above l0 or no root at all (E below the
    minimum of V: the Newton step turns back) is a status."""
    p, energy = sym("p_b"), sym("E_ab")
    stiffness = k_c
    # V - E from the quartic (153) (the registry checks it): q^2 (V - E) / q^2
    gap = sp.expand(bottom_quartic() / q_r**2).subs({q_r: _Q, p_th: p, E: energy})
    rest = (gap + energy).subs(p, 0)  # the spring-and-gravity part of V
    slope = sp.diff(gap, _Q)
    q_min = l0 - m * g_s / stiffness  # minimum of the spring-and-gravity part
    rest_min = rest.subs(_Q, q_min)
    q1 = q_min - sp.sqrt(2 * (energy - rest_min) / stiffness)
    q2 = sp.Abs(p) / sp.sqrt(2 * m * (energy - rest_min))
    start = (q1 + q2 + sp.Abs(q1 - q2)) / 2
    return Kernel(
        name="bottom_quartic",
        summary="Bottom leg length of (153): the compressing root of the quartic in (0, l0] (Newton).",
        equations=("153",),
        args=(
            Arg(p, "angular momentum p_th at the bottom [kg m^2/s]"),
            Arg(energy, "total energy E_ab [J]"),
            catalog.PARAMS["m"],
            catalog.PARAMS["l0"],
            catalog.PARAMS["k_c"],
            catalog.PARAMS["g_s"],
        ),
        steps=(
            Stage(
                ((sym("q_start"), start),),
                (Guard(energy > rest_min, "NO_REAL_SOLUTION", "E_ab above the minimum of the potential"),),
                comment="a start left of the root: V >= E there",
            ),
            Iterate(
                state=((_Q, sym("q_start")),),
                body=(
                    Stage(
                        ((sym("slope"), slope),),
                        (Guard(sym("slope") < 0, "NO_REAL_SOLUTION", "V decreasing left of the root"),),
                    ),
                ),
                update=(_Q - gap / sym("slope"),),
                max_iter=sp.Integer(QUARTIC_PASSES),
                tol=sp.Float(1e-12),  # 1e-15 l0: not reached near a tangent root (round-off)
                scales=(l0,),
                count=sym("passes"),
                fail_status="NOT_CONVERGED",
                comment="Newton's method on V - E: monotone from the left",
            ),
            Stage(
                ((sym("q_r_b"), _Q),),
                (Guard(_Q <= l0, "NO_REAL_SOLUTION", "the bottom root is at most l0"),),
            ),
        ),
        outputs=Group("", (Field("q_r_b", "bottom leg length of (153)", "m"),)),
        module="geyer_vs",
    )


CONTINUITY = Option(
    "continuity",
    "the second half's a_ba, b_ba: how the leg length joins at the bottom",
    "energy",
    (
        ("report", "(103)-(104) with E_ab the touchdown's total energy (27): q_r jumps at the bottom"),
        ("constrained", "b_ba of (104) as in report, a_ba from the continuity constraint (111)"),
        ("energy", "(103)-(104) with E_ab the energy the first half conserves: continuous, (110) holds"),
    ),
    roles=("accuracy-variants", "stiffness-variants"),
)
GRAVITY = Option(
    "gravity",
    "virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and [t_b, t_lo]); each half "
    "runs with its mean momentum, the rates with the momentum at that instant",
    "none",
    (
        ("none", "p_th conserved (Remark 2)"),
        ("type3", "(65) per half: the trapezoid rule on the torque at the half's ends"),
        ("type4", "(76) per half: the torque at the half's average leg length from (11), at its ends"),
    ),
    roles=("accuracy-variants", "stiffness-variants"),
)


class _Names:
    """Kernel names of one pass of the map: ``prefix`` + name (the fixed-point passes use ``i_``)."""

    def __init__(self, prefix: str = ""):
        self.prefix = prefix

    def __call__(self, name: str) -> sp.Symbol:
        return sym(self.prefix + name)

    def ab(self, name: str) -> sp.Symbol:
        return self(f"ab_{name}")

    def ba(self, name: str) -> sp.Symbol:
        return self(f"ba_{name}")


def _first_half(inp: MapInputs, n: _Names, P1: sp.Basic) -> tuple[Step, ...]:
    """Apex to bottom (78)-(89): Geyer's solution with k_c from the touchdown state with the half's
    mean momentum p_td + P1/2, to phase 3 pi/2; the bottom momentum p_td + P1."""
    solution = geyer.solution_kernel()
    p = inp.params
    q_r_td, q_rd_td, _, _ = inp.touchdown
    bottom = geyer.event_states()["bottom"]
    names = {x: n.ab(x.name) for x in (omega, omega0_hat, a, b, geyer.PHASE_TD, geyer.S_TD)}
    return (
        Stage(
            ((n("q_thd_eff"), (sym("p_td") + P1 / 2) / (m * q_r_td**2)),),
            comment="the first half's mean momentum as a touchdown rate",
        ),
        Call(
            solution,
            {
                "q_r_td": q_r_td,
                "q_rd_td": q_rd_td,
                "q_thd_td": n("q_thd_eff"),
                **{q: p[q] for q in ("m", "l0", "g_s")},
                "k": p["k_c"],
            },
            {o: f"{n.prefix}ab_{o}" for o in solution.output_names},
            comment="eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state",
        ),
        Stage(
            (
                (n("t_bottom"), (BOTTOM_PHASE - n.ab("phase_td")) / n.ab("omega0_hat")),
                (n("bottom_q_r"), bottom[0].subs(names)),
                (n("bottom_q_rd"), sp.S.Zero),
                (n("bottom_q_th"), bottom[2].subs(names)),
                (n("p_b"), sym("p_td") + P1),
                (n("bottom_q_thd"), n("p_b") / (m * n("bottom_q_r") ** 2)),
                (n("rho_b"), n("bottom_q_r") / l0 - 1),
            ),
            comment="eqs (79)-(81): the bottom at phase 3 pi/2",
        ),
    )


def _second_half(inp: MapInputs, n: _Names, P2: sp.Basic) -> tuple[Step, ...]:
    """Bottom to apex (90)-(105) with k_d and the energy jump (97)-(98), a_ba and b_ba per option,
    with the half's mean momentum p_b + P2/2 (p_b without a correction: omega_ba = omega_ab (100))."""
    p = inp.params
    sol = half_solution(k_d)
    to_w = {omega: n.ba("omega")}
    taylor = sp.series(geyer.dimensionless_energy(), rho, 0, 3).removeO()
    eps_energy = taylor.subs({rho: n("rho_b"), rho_d: 0, omega: n.ba("omega"), omega0: sp.sqrt(k_c / m)})
    jump = energy_jump().subs(q_r, n("bottom_q_r"))
    choice = inp.options["continuity"]
    eps_ba, eps_td = n("eps_ba"), 2 * (sym("E_td") + jump) / (m * l0**2)
    return (
        Stage(
            (
                (n.ba("omega"), (n("p_b") + P2 / 2) / (m * l0**2)),
                (n.ba("omega0_hat"), sol["omega0_hat"].subs(to_w)),
                (n.ba("a_free"), sol["a"].subs(to_w)),
            ),
            (
                Guard(
                    n("rho_b") < n.ba("a_free"),
                    "RECOMPRESSION",
                    "with k_d the bottom lies below the centre a_ba of (90): the leg extends",
                ),
            ),
            comment="eqs (100)-(103): omega_ba from the momentum, omega0_ba^2 = k_d/m",
        ),
        Switch(
            inp.opt("continuity"),
            (
                (
                    choice.code("report"),
                    (Stage(((eps_ba, eps_td),), comment="eqs (97)-(99), E_ab the energy (27)"),),
                ),
                (choice.code("constrained"), (Stage(((eps_ba, eps_td),), comment="as report"),)),
                (
                    choice.code("energy"),
                    (
                        Stage(
                            ((eps_ba, eps_energy + 2 * jump / (m * l0**2)),),
                            comment="eqs (97)-(99) with E_ab Geyer's energy (8) at the bottom",
                        ),
                    ),
                ),
            ),
            comment="E_ab of (98)",
        ),
        Stage(
            ((n.ba("b2"), sol["b2"].subs(to_w).subs(epsilon, eps_ba)),),
            (Guard(n.ba("b2") > 0, "NO_REAL_SOLUTION", "eq (104): real amplitude b_ba"),),
        ),
        Stage(
            (
                (n.ba("b"), sp.sqrt(n.ba("b2"))),
                (
                    n.ba("a"),
                    sp.Piecewise(
                        (n("rho_b") + n.ba("b"), choice.is_("constrained")),
                        (n.ba("a_free"), True),
                    ),
                ),
            ),
            comment="eq (104); eq (103), or (111) when constrained",
        ),
        Call(
            geyer.liftoff_phase_kernel(),
            {"a": n.ba("a"), "b": n.ba("b"), "l0": p["l0"], "q_r_lo": p["q_r_lo"]},
            {"phase_lo": f"{n.prefix}ba_phase_lo", "s_lo": f"{n.prefix}ba_s_lo"},
            comment="eq (94): the liftoff phase of the second half",
        ),
    )


def second_state(phase: sp.Basic, n: _Names | None = None) -> tuple[sp.Basic, ...]:
    """(90)-(92) at ``phase`` of the second half (bottom at 3 pi/2): (11), (19), (17) (the rate with
    the half's mean momentum)."""
    n = n or _Names()
    names = {omega: n.ba("omega"), omega0_hat: n.ba("omega0_hat"), a: n.ba("a"), b: n.ba("b")}
    shift = {geyer.PHASE: phase, geyer.PHASE_TD: BOTTOM_PHASE, q_th_td: n("bottom_q_th")}
    return tuple(e.subs(shift).subs(names) for e in geyer.state_at_phase())


def _liftoff(inp: MapInputs, n: _Names, P2: sp.Basic) -> tuple[Stage, ...]:
    """The liftoff state; with a gravity correction its radial speed comes from the energy after the
    bottom (the touchdown's energy (27) plus the jump (97) at the bottom), as in the ``mean`` reading
    of section 4, since (11) knows nothing of the changed momentum."""
    state = second_state(n.ba("phase_lo"), n)
    trig = {
        sp.sin(n.ba("phase_lo")): n.ba("s_lo"),
        sp.cos(n.ba("phase_lo")): sp.sqrt(1 - n.ba("s_lo") ** 2),
    }
    no_gravity = inp.options["gravity"].is_("none")
    p_lo = n("p_b") + P2
    energy = sym("E_td") + energy_jump().subs(q_r, n("bottom_q_r"))
    square = liftoff_radial_speed(k_d).subs(
        {q_r: q_r_lo, q_th: n("liftoff_q_th"), P_SYM: p_lo, E_SYM: energy}
    )
    return (
        Stage(
            (
                (n("t_stance"), n("t_bottom") + (n.ba("phase_lo") - BOTTOM_PHASE) / n.ba("omega0_hat")),
                (n("liftoff_q_r"), q_r_lo),
                (n("liftoff_q_th"), state[2].subs(trig)),
                (n("liftoff_q_thd"), p_lo / (m * q_r_lo**2)),
                (n("q_rd_lo_sq"), square),
            ),
            (
                Guard(sp.Abs(n("liftoff_q_th")) < sp.pi / 2, "FALL", "the leg stays above horizontal"),
                Guard(sp.Or(no_gravity, n("q_rd_lo_sq") >= 0), "ENERGY_DEFICIT", "q_rd_lo^2 from the energy"),
            ),
            comment="eqs (90)-(94) at liftoff",
        ),
        Stage(
            (
                (
                    n("liftoff_q_rd"),
                    sp.Piecewise((state[1].subs(trig), no_gravity), (sp.sqrt(n("q_rd_lo_sq")), True)),
                ),
            ),
            comment="q_rd_lo: (11) without a gravity correction, the energy with one",
        ),
    )


def _impulses(inp: MapInputs, n: _Names) -> Switch:
    """``<prefix>P_new1``, ``<prefix>P_new2``: each half's stance impulse (type 3 or 4 of section 4
    on [t_td, t_b] and [t_b, t_lo]) along the pass named by ``n``."""
    average = average_leg_length("eq11")  # (11) on its own time axis

    def over(half, t_from, t_to):
        w = half("omega0_hat")
        times = {T_I: t_from / w, T_F: t_to / w}
        return average.subs(times).subs({a: half("a"), b: half("b"), omega0_hat: w})

    return half_impulse_switch(
        inp,
        n.prefix,
        (n("t_bottom"), n("t_stance")),
        (q_th_td, n("bottom_q_th"), n("liftoff_q_th")),
        (q_r_td, n("bottom_q_r"), n("bottom_q_r"), q_r_lo),
        (over(n.ab, n.ab("phase_td"), BOTTOM_PHASE), over(n.ba, BOTTOM_PHASE, n.ba("phase_lo"))),
        "(11)",
    )


def _pass(inp: MapInputs, n: _Names, P1: sp.Basic, P2: sp.Basic) -> tuple[Step, ...]:
    return _first_half(inp, n, P1) + _second_half(inp, n, P2) + _liftoff(inp, n, P2)


def _build(inp: MapInputs) -> MapBuild:
    P1, P2 = sym("P_c_compression"), sym("P_c_decompression")
    trial = _Names("i_")
    steps = (
        touchdown_invariants(k_c),
        *half_fixed_point(inp, trial.prefix, _pass(inp, trial, P1, P2), _impulses(inp, trial)),
    )

    def state_at(time: sp.Symbol) -> tuple[Step, ...]:
        first = geyer.state_kernel()
        n = trial
        ab = {x: n.ab(x) for x in ("omega", "omega0_hat", "a", "b", "phase_td")}
        second = second_state(BOTTOM_PHASE + n.ba("omega0_hat") * (time - n("t_bottom")), n)
        t_b, t_s = n("t_bottom"), n("t_stance")
        rates = (
            (sym("p_td") + P1 * time / t_b) / (m * sym("c_q_r") ** 2),
            (n("p_b") + P2 * (time - t_b) / (t_s - t_b)) / (m * second[0] ** 2),
        )
        return steps + (
            Call(
                first,
                {"phase": ab["phase_td"] + ab["omega0_hat"] * time, "q_th_td": q_th_td, "l0": l0, **ab},
                {f.name: f"c_{f.name}" for f in catalog.POLAR},
                comment="eqs (78)-(79): the first half",
            ),
            Stage(
                tuple(
                    (
                        sym(f.name),
                        sp.Piecewise(
                            (sym(f"c_{f.name}") if f.name != "q_thd" else rates[0], time <= t_b),
                            (second[i] if f.name != "q_thd" else rates[1], True),
                        ),
                    )
                    for i, f in enumerate(catalog.POLAR)
                ),
                comment="the piecewise stance map of section 5.1 ((112)-(113)): (78)-(79) up to t_b, "
                "(90)-(92) after; the rates with the momentum at t",
            ),
        )

    return MapBuild(steps=steps, state_at=state_at, helpers=(quartic_kernel(),))


#: The family page of this module's map (derive/maps/__init__.py: :func:`~slipmaps.derive.maps.family_pages`).
PAGE = "variable"

MAPS = (
    MapSpec(
        name="geyer-vs",
        title="Simple variable-stiffness map (Geyer et al. per half)",
        section="5.1",
        equations=tuple(str(n) for n in range(78, 114) if n != 95),
        params=("m", "l0", "k_c", "k_d", "g_s"),
        build=_build,
        # the passes matter only with a gravity correction, off by default: the accuracy study
        # measures the correction through GRAVITY's values, at the default pass count
        options=(CONTINUITY, GRAVITY, iterations_option(100, ("convergence-passes",)), tol_option(1e-12)),
        extras=HALF_EXTRAS,
        summary="Geyer et al.'s map with k_c to the bottom, the energy jump (97)-(98), again with k_d to "
        "liftoff; optionally a gravity correction per half",
        notes="Section 5.1: apex to bottom (78)-(89) with k_c, bottom to apex (90)-(105) with k_d and "
        "E_ba = E_ab + (k_d - k_c)(l0 - q_r_b)^2/2; option continuity chooses (103)-(104) with the "
        "touchdown energy (27), the constraint (111), or (103)-(104) with the energy of the first half; "
        "option gravity adds type 3 or 4 of section 4 on each half.",
        roles=("default",),
    ),
)
