"""The gravity-correction family (report section 4, eqs 46-77, and the type-5 design of
docs/type5.md): the generated kernels against independent reconstructions from Geyer et al.'s map,
and the type-5 derivation's identities."""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
import sympy as sp
from slipmaps.derive import symbols as S
from slipmaps.derive.maps import geyer as d_geyer
from slipmaps.derive.maps import gravity as d_gravity
from slipmaps.derive.maps import gravity_type5 as t5

P = slipmaps.SlipParams(m=80.0, l0=1.0, k=7848.0)  # k l0/(m g) = 10, the Yu protocol's leg
#: Nonsymmetric touchdowns: slow with a flat leg, moderate, fast with a steep leg.
TOUCHDOWNS = [(1.0, -1.2, 0.45, -2.0), (1.0, -1.5, 0.40, -3.0), (1.0, -2.0, 0.30, -5.0)]
TYPES = [f"gravity-type{i}" for i in range(5)]


def _energy(state, p=P) -> float:
    q_r, q_rd, q_th, q_thd = state
    return (
        0.5 * p.m * (q_rd**2 + q_r**2 * q_thd**2)
        + 0.5 * p.k * (p.l0 - q_r) ** 2
        + p.m * p.g_s * q_r * math.cos(q_th)
    )


def _with_momentum(td, p_traj):
    """The touchdown state ``td`` with the angular momentum ``p_traj`` (an effective rate)."""
    q_r, q_rd, q_th, _ = td
    return (q_r, q_rd, q_th, p_traj / (P.m * q_r**2))


def _geyer_with_momentum(td, p_traj):
    """Geyer et al.'s map from ``td`` with the angular momentum ``p_traj``."""
    return slipmaps.stance("geyer", P, _with_momentum(td, p_traj))


def _impulse(kind: int, td, g) -> float:
    """P_c of types 0-2 (2 samples) from the Geyer result ``g`` started at ``td``: (49), (52), (62)."""
    m, l0, gs = P.m, P.l0, P.g_s
    length = {0: l0, 1: (l0 + g.bottom_q_r) / 2}.get(kind)
    if length is None:  # type 2: mean of q_r over the stance, by quadrature of Geyer's trajectory
        t, states, _ = slipmaps.trajectory("geyer", P, td, np.linspace(0.0, g.t_stance, 4001))
        length = np.trapezoid(states[:, 0], t) / g.t_stance
    return g.t_stance * m * gs * length * (math.sin(td[2]) + math.sin(g.liftoff_q_th)) / 2


@pytest.mark.parametrize("kind", [0, 1, 2])
@pytest.mark.parametrize("td", TOUCHDOWNS)
def test_eq50_report_reading_one_pass_is_geyer_with_the_corrected_momentum(kind, td):
    """reading=report, one pass: P_c from Geyer's map, then Geyer's map with p_th + P_c (eq 50)."""
    p_td = P.m * td[0] ** 2 * td[3]
    pc = _impulse(kind, td, slipmaps.stance("geyer", P, td))
    expect = _geyer_with_momentum(td, p_td + pc)
    got = slipmaps.stance(f"gravity-type{kind}", P, td, reading="report", iterations=1, tol=0.0)
    assert got.ok and expect.ok
    # measured: 1.9e-15 (types 0, 1); type 2's reconstruction averages q_r by the trapezoid rule on
    # 4001 points, 5.4e-9 on P_c and 1.3e-9 on the states
    rel = 1e-12 if kind < 2 else 1e-7
    assert got.P_c == pytest.approx(pc, rel=rel)
    for key in (
        "t_stance",
        "t_bottom",
        "bottom_q_r",
        "bottom_q_th",
        "liftoff_q_rd",
        "liftoff_q_th",
        "liftoff_q_thd",
    ):
        assert got[key] == pytest.approx(expect[key], rel=rel, abs=1e-12), key


@pytest.mark.parametrize("kind", [0, 1, 2])
@pytest.mark.parametrize("td", TOUCHDOWNS)
def test_eq50_mean_reading_fixed_point_is_self_consistent(kind, td):
    """reading=mean at its fixed point: the trajectory runs with p_td + P_c/2 (Geyer's map with that
    momentum gives its angles and times), P_c is the impulse formula on that trajectory, the liftoff
    rate is (p_td + P_c)/(m q_r_lo^2) and the liftoff state has the touchdown's exact energy (27)."""
    p_td = P.m * td[0] ** 2 * td[3]
    got = slipmaps.stance(f"gravity-type{kind}", P, td, iterations=200, tol=1e-13)
    assert got.ok and got.passes < 200
    traj = _geyer_with_momentum(td, p_td + got.P_c / 2)
    pc = _impulse(kind, _with_momentum(td, p_td + got.P_c / 2), traj)
    # measured: 8.8e-13 (types 0, 1: the fixed point's tolerance), 5.3e-9 (type 2: the trapezoid
    # average of the reconstruction); the states below 2e-15
    assert got.P_c == pytest.approx(pc, rel=1e-7 if kind == 2 else 1e-10)
    assert got.liftoff_q_th == pytest.approx(traj.liftoff_q_th, rel=1e-12)
    assert got.t_stance == pytest.approx(traj.t_stance, rel=1e-12)
    assert got.liftoff_q_thd == pytest.approx((p_td + got.P_c) / (P.m * P.q_r_lo**2), rel=1e-12)
    assert _energy(got.liftoff) == pytest.approx(_energy(td), rel=1e-12)
    # the bottom rate uses the momentum accumulated by then (constant torque: P_c t_b / t_s)
    p_b = p_td + got.P_c * got.t_bottom / got.t_stance
    assert got.bottom_q_thd == pytest.approx(p_b / (P.m * got.bottom_q_r**2), rel=1e-12)


@pytest.mark.parametrize("name", [*TYPES, "gravity-type5"])
def test_zero_iterations_is_geyers_trajectory(name):
    """No correction pass: P_c = 0, so the trajectory is Geyer et al.'s (only q_rd_lo may differ:
    the mean reading takes it from the energy)."""
    td = TOUCHDOWNS[1]
    got = slipmaps.stance(name, P, td, iterations=0, tol=0.0)
    g = slipmaps.stance("geyer", P, td)
    assert got.P_c == 0.0 and got.passes == 0.0
    for key in ("t_stance", "bottom_q_r", "liftoff_q_thd"):
        assert got[key] == pytest.approx(g[key], rel=1e-12), key
    if name != "gravity-type5":  # type 5's leg angle keeps the second-order term of 1/(1+rho)^2 (T5.6)
        assert got.liftoff_q_th == pytest.approx(g.liftoff_q_th, abs=1e-12)


def test_eq65_type3_whole_stance_at_rest_length_is_type0():
    """The report's claim, on the generated kernels: type 3 on [t_td, t_lo] with q_r_td = q_r_lo = l0
    is type 0 (both 2-sample, both readings). Measured: identical to the last bit."""
    for td in TOUCHDOWNS:
        for reading in ("mean", "report"):
            a = slipmaps.stance("gravity-type3", P, td, interval="stance", reading=reading)
            b = slipmaps.stance("gravity-type0", P, td, reading=reading, iterations=100, tol=1e-12)
            assert a.P_c == pytest.approx(b.P_c, rel=1e-12) and a.liftoff == pytest.approx(
                b.liftoff, rel=1e-12
            )


def test_eq76_type4_whole_stance_is_type2():
    """Measured: identical to the last bit."""
    for td in TOUCHDOWNS:
        a = slipmaps.stance("gravity-type4", P, td, interval="stance")
        b = slipmaps.stance("gravity-type2", P, td)
        assert a.P_c == pytest.approx(b.P_c, rel=1e-12) and a.liftoff == pytest.approx(b.liftoff, rel=1e-12)


def test_eq55_eq61_three_average_leg_lengths_agree_at_rest_length():
    """(11), (21) and (23) describe the same stance when q_r_td = l0: type 2's three options agree
    (measured: 9.3e-16 relative on P_c)."""
    for td in TOUCHDOWNS:
        ref = slipmaps.stance("gravity-type2", P, td, leg_length="eq11")
        for source in ("eq21", "eq23"):
            other = slipmaps.stance("gravity-type2", P, td, leg_length=source)
            assert other.P_c == pytest.approx(ref.P_c, rel=1e-9), source


def test_the_report_reading_iterated_can_reverse_the_momentum():
    """Finding (docs/gravity.md): the report's reading iterated to its fixed point can flip the sign
    of the angular momentum on a slow, tall hop (Yu protocol, 65 deg, h = 0.95 m, v = 2 m/s): the leg
    sweeps backward. The mean reading keeps it."""
    angle = math.radians(25.0)
    report = slipmaps.apex_return(
        "gravity-type2", P, 0.95, 2.0, angle, reading="report", iterations=300, tol=1e-12
    )
    mean = slipmaps.apex_return("gravity-type2", P, 0.95, 2.0, angle)
    exact = slipmaps.apex_return("exact", P, 0.95, 2.0, angle)
    assert exact.ok and mean.ok
    assert report.status == slipmaps.Status.LIFTOFF_BACKWARD


# ------------------------------------------------------------------------------------------------
# Type 5: the identities its derivation rests on (docs/type5.md)
# ------------------------------------------------------------------------------------------------
def test_t5_2_gauss_rule_gives_the_impulse_of_the_interpolated_torque():
    T = t5.T_PREV
    c = dict(zip(t5.C, t5.torque_quadratic(), strict=True))
    impulse = (t5.momentum(T) - t5.P_TD).subs(c)
    gauss = T / 2 * sum(w * tau for w, tau in zip(t5.GL_W, t5.TAU, strict=True))
    assert sp.simplify(impulse - gauss) == 0


def test_t5_1_quadratic_passes_through_the_nodal_torques():
    c = t5.torque_quadratic()
    for ti, tau in zip(t5.nodes(t5.T_PREV), t5.TAU, strict=True):
        assert sp.simplify(c[0] + c[1] * ti + c[2] * ti**2 - tau) == 0


def test_t5_5_is_geyers_quadratic_at_r_c_0_and_g_eff_g_s():
    lam, mu = t5.radial_quadratic()
    g_lam, g_mu, _ = d_geyer.radial_quadratic()
    assert sp.simplify(lam.subs(t5.R_C, 0) - g_lam) == 0
    assert sp.simplify(mu.subs({t5.R_C: 0, t5.G_EFF: S.g_s}) - g_mu) == 0


def test_t5_6_leg_angle_derivative_is_the_rate():
    rate = sp.diff(t5.leg_angle(), t5.T_NOW)
    x = t5.W_HAT * t5.T_NOW + t5.PH_TD
    expect = t5.momentum(t5.T_NOW) * (t5.K[0] + t5.K[1] * sp.sin(x) + t5.K[2] * sp.cos(2 * x))
    expect = expect / (S.m * S.l0**2)
    point = {s: sp.Rational(i + 2, 7) for i, s in enumerate(sorted(rate.free_symbols, key=str))}
    assert abs(float((rate - expect).subs(point))) < 1e-12
    assert t5.leg_angle().subs(t5.T_NOW, 0) == S.q_th_td


def test_t5_6_rate_factor_is_the_expansion_of_inverse_square():
    x = sp.Symbol("x", real=True)
    k0, k1, k2 = t5.rate_factor()
    series = t5.inverse_square_expansion().subs(S.rho, t5.A_ + t5.B_ * sp.sin(x))
    assert sp.simplify(sp.expand(series - (k0 + k1 * sp.sin(x) + k2 * sp.cos(2 * x)))) == 0


def test_type5_fixed_point_conserves_energy_and_uses_the_end_momentum():
    td = TOUCHDOWNS[0]
    got = slipmaps.stance("gravity-type5", P, td)
    assert got.ok and 1 < got.passes < 100
    # measured: 1.1e-16 (rate), 6.2e-16 (energy)
    p_td = P.m * td[0] ** 2 * td[3]
    assert got.liftoff_q_thd == pytest.approx((p_td + got.P_c) / (P.m * P.q_r_lo**2), rel=1e-12)
    assert _energy(got.liftoff) == pytest.approx(_energy(td), rel=1e-12)


def test_liftoff_speed_from_energy_lies_on_the_energy_level():
    """q_rd = +sqrt(radicand) puts the state (q_r, q_rd, q_th, p/(m q_r^2)) on H = E of (27)."""
    from slipmaps.derive.model import mechanics

    q_rd_sq = d_gravity.liftoff_radial_speed()
    energy = mechanics.stance_energy().subs(
        {S.q_rd: sp.sqrt(q_rd_sq), S.q_thd: d_gravity.P_SYM / (S.m * S.q_r**2)}
    )
    assert sp.simplify(energy - d_gravity.E_SYM) == 0


# ----------------------------------------------------------------------------------------------
# Types 0-4 are one family (derive/mapspec.py ``MapSpec.family``): one module, one layout, their
# kernels one body (derive/share.py) that calls each type's impulse rule.


def test_family_members_share_one_layout_and_body():
    import inspect

    from slipmaps.generated import gravity, gravity_jacobian
    from slipmaps.runtime.api.index import get

    layouts = set()
    for name in TYPES:
        info = get(name)
        assert {s.module for s in info.kernels.values()} == {"gravity", "gravity_jacobian"}
        layouts.add(info.kernels["stance"].p)
        # every slot of the shared record is filled: by an option of the map or by what it fixes
        public = {o.name for o in info.options}
        assert set(info.kernels["stance"].p) - set(P.values()) == public | set(info.fixed)
        assert not public & set(info.fixed)
        # each role kernel is an entry of a body the types share, passing the type's own rule
        for role, spec in info.kernels.items():
            module = gravity_jacobian if role.endswith("_jacobian") else gravity
            source = inspect.getsource(getattr(module, spec.name).py_func)
            assert "_shared" in source, (name, role)
    assert len(layouts) == 1


@pytest.mark.parametrize("kind", range(5))
def test_family_member_passes_its_own_impulse_rule(kind):
    import inspect

    from slipmaps.generated import gravity

    source = inspect.getsource(getattr(gravity, f"gravity_type{kind}_stance").py_func)
    assert f"gravity_impulse_type{kind})" in source
    assert all(f"gravity_impulse_type{j})" not in source for j in range(5) if j != kind)


def _member(**fields):
    from slipmaps.derive.mapspec import MapSpec

    base = d_gravity.MAPS[0]
    kwargs = {
        "name": "gravity-typex",
        "title": base.title,
        "section": base.section,
        "equations": base.equations,
        "params": base.params,
        "requires": base.requires,
        "build": base.build,
        "options": base.options,
        "family": d_gravity.FAMILY,
        "fixed": base.fixed,
    }
    return MapSpec(**{**kwargs, **fields})


def test_family_member_declaration_is_checked():
    assert _member().fixed_codes() == d_gravity.MAPS[0].fixed_codes()
    fixed = dict(d_gravity.MAPS[0].fixed)
    with pytest.raises(ValueError, match=r"leaves \['interval'\] unset"):
        _member(fixed=tuple((n, v) for n, v in fixed.items() if n != "interval"))
    with pytest.raises(ValueError, match=r"fixes \['samples'\] it may not"):
        _member(fixed=tuple(fixed.items()) + (("samples", 3),))
    with pytest.raises(ValueError, match="outside its domain"):
        _member(fixed=(("samples", 5), ("leg_length", "eq11")), options=d_gravity.MAPS[3].options)
    with pytest.raises(ValueError, match="not in"):
        _member(fixed=tuple({**fixed, "leg_length": "eq99"}.items()))
    with pytest.raises(ValueError, match="in the family's order"):
        _member(options=tuple(reversed(d_gravity.MAPS[0].options)))
    with pytest.raises(ValueError, match="option samples is not the family's"):
        other = d_gravity.Option("samples", "x", 2, low=2, high=4, integer=True)
        _member(options=tuple(other if o.name == "samples" else o for o in d_gravity.MAPS[0].options))


def test_a_members_kernels_are_its_own_in_its_familys_module():
    member = d_gravity.MAPS[2]
    assert member.module_name == "gravity" and member.stance_kernel().name == "gravity_type2_stance"
    assert member.stance_kernel().module == "gravity"
    assert [a.name for a in member.option_args()] == [o.name for o in d_gravity.FAMILY.options]
