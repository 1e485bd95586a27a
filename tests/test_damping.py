"""The leg damping ``c`` (derive/params.py): the exact map's damped stance (generated/exact_stance.py)
against an independent integration, its two liftoff conventions, the energy it dissipates, its
Jacobian, and the maps that refuse it.

The damped stance (derive/model/mechanics.py, registry entry sec2.2.1-damped): the radial force is
-k (q_r - l0) - c q_rd, k = k_c until the bottom (q_rd = 0) and k_d after it; with
``liftoff="force"`` (default) the stance ends where the leg force k_d (l0 - q_r) - c q_rd falls to 0
(the ground cannot pull) or at q_r = q_r_lo, whichever comes first; with ``liftoff="length"`` at
q_r = q_r_lo. The reference here is written out on its own (its right-hand side, its events) and
integrated by scipy's solve_ivp (DOP853, rtol 1e-12), carrying the dissipated energy
W = integral of c q_rd^2 dt as a fifth component.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
from hypothesis import given
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from slipmaps.generated import exact_stance as ej
from slipmaps.generated.status import Status
from slipmaps.runtime.api import index
from slipmaps.runtime.api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from slipmaps.runtime.cli.app import main
from test_exact_jacobian import stance_outputs, worst_column_error

NAMES = ej.STANCE_NAMES


def critical(p: SlipParams) -> float:
    """The leg's critical damping 2 sqrt(k_c m) [N s/m]."""
    return 2.0 * math.sqrt(p.k_c * p.m)


def _field(p: SlipParams, k: float):
    def rhs(_t, y):
        q_r, q_rd, q_th, q_thd, _ = y
        force = k * (p.l0 - q_r) - p.c * q_rd
        q_rdd = q_r * q_thd**2 - p.g_s * math.cos(q_th) + force / p.m
        q_thdd = p.g_s * math.sin(q_th) / q_r - 2.0 * q_rd * q_thd / q_r
        return [q_rd, q_rdd, q_thd, q_thdd, p.c * q_rd**2]

    return rhs


def _event(fun, direction):
    def event(t, y):
        return fun(y)

    event.terminal, event.direction = True, direction
    return event


def reference(p: SlipParams, touchdown, liftoff: str = "force") -> tuple[dict, float]:
    """The damped stance by solve_ivp (module docstring): (its stance row by name, the energy the
    damper dissipated [J])."""
    tol = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-13, "dense_output": False}
    bottom = solve_ivp(
        _field(p, p.k_c), (0.0, 10.0), [*touchdown, 0.0], events=_event(lambda y: y[1], 1.0), **tol
    )
    assert bottom.status == 1 and len(bottom.t_events[0]) == 1
    t_b, y_b = bottom.t_events[0][0], bottom.y_events[0][0].copy()
    y_b[1] = 0.0
    events = [_event(lambda y: y[0] - p.q_r_lo, 1.0)]
    if liftoff == "force":
        events.append(_event(lambda y: p.k_d * (p.l0 - y[0]) - p.c * y[1], -1.0))
    lift = solve_ivp(_field(p, p.k_d), (t_b, t_b + 10.0), y_b, events=events, **tol)
    assert lift.status == 1
    hit = [(e[0], y[0]) for e, y in zip(lift.t_events, lift.y_events, strict=True) if len(e)]
    t_lo, y_lo = min(hit, key=lambda h: h[0])
    row = {"t_bottom": t_b, "t_stance": t_lo}
    for j, q in enumerate(("q_r", "q_rd", "q_th", "q_thd")):
        row[f"bottom_{q}"], row[f"liftoff_{q}"] = y_b[j], y_lo[j]
    return row, y_lo[4]


def energy(p: SlipParams, k: float, state) -> float:
    """The stance energy of a polar state with stiffness k (kinetic + spring + gravity above the toe)."""
    q_r, q_rd, q_th, q_thd = state
    return (
        0.5 * p.m * (q_rd**2 + (q_r * q_thd) ** 2)
        + 0.5 * k * (p.l0 - q_r) ** 2
        + p.m * p.g_s * q_r * math.cos(q_th)
    )


TOUCHDOWN = (1.0, -1.2, 0.35, -4.6)
ROBOT_TOUCHDOWN = (0.25, -0.5, 0.3, -6.0)
#: (params, touchdown, liftoff): light to strong damping (fractions of critical), k_c != k_d, a
#: liftoff length below l0, both conventions.
CASES = [
    pytest.param(HUMAN_RUNNER.with_(c=0.02 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-2%"),
    pytest.param(HUMAN_RUNNER.with_(c=0.1 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-10%"),
    pytest.param(HUMAN_RUNNER.with_(c=0.2 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-20%"),
    pytest.param(
        HUMAN_RUNNER.with_(c=0.1 * critical(HUMAN_RUNNER)), TOUCHDOWN, "length", id="human-10%-length"
    ),
    pytest.param(
        HUMAN_RUNNER.with_(k_d=24_000.0, c=0.1 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-kd24k"
    ),
    pytest.param(
        HUMAN_RUNNER.with_(q_r_lo=0.97, c=0.05 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-qrlo"
    ),
    pytest.param(
        ROBOT_HOPPER.with_(c=0.1 * critical(ROBOT_HOPPER)), ROBOT_TOUCHDOWN, "force", id="robot-10%"
    ),
]


@pytest.mark.parametrize(("params", "touchdown", "liftoff"), CASES)
def test_damped_stance_matches_an_independent_integration(params, touchdown, liftoff):
    got = slipmaps.stance("exact", params, touchdown, liftoff=liftoff)
    assert got.status == Status.OK
    ref, _ = reference(params, touchdown, liftoff)
    worst = max(abs(got.values[n] - ref[n]) for n in NAMES)
    # Measured over CASES: 1.6e-12 to 6.1e-11 (SI units: s, m, m/s, rad, rad/s; the largest on
    # liftoff_q_rd at 10 % of critical damping).
    assert worst < 1e-9, worst


def test_damped_liftoff_is_where_the_leg_force_falls_to_zero():
    p = HUMAN_RUNNER.with_(c=0.1 * critical(HUMAN_RUNNER))
    force = slipmaps.stance("exact", p, TOUCHDOWN)
    length = slipmaps.stance("exact", p, TOUCHDOWN, liftoff="length")
    q_r, q_rd = force.values["liftoff_q_r"], force.values["liftoff_q_rd"]
    assert force.status == length.status == Status.OK
    assert q_r < p.l0 - 0.01 and q_rd > 0.0  # measured q_r = 0.98863 m
    leg_force = p.k_d * (p.l0 - q_r) - p.c * q_rd
    # Measured: 1.4e-13 N here, at most 2.6e-12 N over CASES' force liftoffs (k_d l0 = 2e4 N).
    assert abs(leg_force) < 1e-10, leg_force
    assert force.values["t_stance"] < length.values["t_stance"]
    assert length.values["liftoff_q_r"] == p.q_r_lo  # the pull ignored: at q_r_lo
    # the liftoff length first when it comes before the force's zero (q_r_lo below it)
    short = p.with_(q_r_lo=0.97)
    assert slipmaps.stance("exact", short, TOUCHDOWN).values["liftoff_q_r"] == short.q_r_lo


def test_energy_falls_by_the_dissipated_work():
    """With k_c = k_d the stance energy only falls (dE/dt = -c q_rd^2): strictly along the stance,
    and from touchdown to liftoff by the reference's W = integral of c q_rd^2 dt."""
    p = HUMAN_RUNNER.with_(c=0.1 * critical(HUMAN_RUNNER))
    res = slipmaps.stance("exact", p, TOUCHDOWN)
    assert res.status == Status.OK
    _, work = reference(p, TOUCHDOWN)
    liftoff = [res.values[f"liftoff_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd")]
    lost = energy(p, p.k_c, TOUCHDOWN) - energy(p, p.k_d, liftoff)
    assert work > 10.0  # measured 11.76 J of 1641 J
    # Measured: |lost - W| = 3.7e-9 J, 2.2e-12 of the energy (over CASES with k_c = k_d: <= 2.3e-12).
    assert abs(lost - work) < 1e-11 * energy(p, p.k_c, TOUCHDOWN), (lost, work)
    t = np.linspace(0.0, res.values["t_stance"], 201)
    _, states, status = slipmaps.trajectory("exact", p, TOUCHDOWN, t=t)
    assert status == Status.OK
    e = np.array([energy(p, p.k_c, s) for s in states])
    assert np.all(np.diff(e) < 0.0), np.max(np.diff(e))


#: Apexes (height / l0, speed / sqrt(g_f l0), touchdown angle [rad]).
STEPS = np.array([(1.0, 1.6, 0.35), (1.1, 1.3, 0.4), (1.0, 1.1, 0.35)])


@pytest.mark.parametrize(
    "params",
    [HUMAN_RUNNER, HUMAN_RUNNER.with_(k_d=24_000.0, q_r_lo=0.98), ROBOT_HOPPER.with_(k_d=1_700.0)],
    ids=["human", "human-kd-qrlo", "robot-kd"],
)
def test_zero_damping_is_the_lossless_map_bit_for_bit(params):
    """c = 0 given or not, liftoff "force" (default) or "length": the same values, bitwise (the
    Jacobians too, but for c's own column: a derivative from c > 0, :func:`test_jacobian_at_zero_damping`)."""
    p = params
    explicit = SlipParams(**{**p.as_dict(), "c": 0.0})
    h, v, a = (STEPS * [p.l0, math.sqrt(p.g_f * p.l0), 1.0]).T
    runs = [{}, {"liftoff": "length"}, {"liftoff": "force"}]
    apex = [slipmaps.apex_return_batch("exact", q, apex_height=h, apex_speed=v, touchdown_angle=a, **o)
            for q in (p, explicit) for o in runs]  # fmt: skip
    assert np.count_nonzero(apex[0].status == Status.OK) >= 2
    td = np.array([ROBOT_TOUCHDOWN if p.l0 < 1.0 else TOUCHDOWN, (0.99 * p.q_r_td, -0.8, 0.2, -3.0)])
    stance = [slipmaps.stance_batch("exact", q, td, **o) for q in (p, explicit) for o in runs]
    jac = [slipmaps.stance_jacobian_batch("exact", q, td, **o) for q in (p, explicit) for o in runs]
    for batch in (apex, stance):
        for other in batch[1:]:
            np.testing.assert_array_equal(other.status, batch[0].status)
            for name in batch[0].names:
                np.testing.assert_array_equal(other[name], batch[0][name])
    keep = [j for j in range(ej.N_IN) if j != ej.C]
    for other in jac[1:]:
        np.testing.assert_array_equal(other.matrix[..., keep], jac[0].matrix[..., keep])


@pytest.mark.parametrize(("params", "touchdown", "liftoff"), CASES)
def test_damped_jacobian_matches_central_differences(params, touchdown, liftoff):
    """Every column, c's included: the variational equations with the damper's term, the saltation at
    the bottom and the map to the liftoff surface (the leg force's zero with "force")."""
    p = params
    jac = slipmaps.stance_jacobian("exact", p, touchdown, liftoff=liftoff)
    assert jac.status == Status.OK
    w0 = np.array([*touchdown, p.k_c, p.k_d, p.c])
    columns = [j for j in range(ej.N_IN) if not (j == 0 and touchdown[0] >= p.l0)]  # q_r_td = l0: no q_r + h
    worst = worst_column_error(p, w0, jac.matrix, columns, liftoff=liftoff)
    # Measured over CASES: 3.1e-11 to 4.9e-9 (test_exact_jacobian.py's measure and step).
    assert worst < 3e-8, worst


@pytest.mark.parametrize(
    ("params", "touchdown"),
    [
        (HUMAN_RUNNER, TOUCHDOWN),
        (HUMAN_RUNNER.with_(q_r_lo=0.97), TOUCHDOWN),
        (ROBOT_HOPPER, ROBOT_TOUCHDOWN),
    ],
    ids=["human", "human-qrlo", "robot"],
)
def test_jacobian_at_zero_damping_is_the_derivative_from_above(params, touchdown):
    """At c = 0 (the domain's edge) c's column is the one-sided derivative toward c > 0, where
    liftoff="force" lifts off on the leg force's zero (at q_r_lo = l0 it meets q_r = l0): against a
    second-order one-sided difference, h = 1e-5 of the critical damping."""
    p = params
    jac = slipmaps.stance_jacobian("exact", p, touchdown)
    assert jac.status == Status.OK
    w0 = np.array([*touchdown, p.k_c, p.k_d, 0.0])
    step = np.zeros(ej.N_IN)
    step[ej.C] = 1e-5 * critical(p)
    f0, f1, f2 = (stance_outputs(p, w0 + i * step) for i in range(3))
    column = jac.matrix[:, ej.C]
    fd = (-f2 + 4.0 * f1 - 3.0 * f0) / (2.0 * step[ej.C])
    # Measured: 2.0e-10 (human), 7.2e-10 (q_r_lo 0.97), 1.7e-9 (robot); h = 1e-4: up to 1.2e-7.
    assert np.max(np.abs(fd - column)) / np.max(np.abs(column)) < 3e-8


E_ROUNDOFF = 2e-11  # relative; measured at most 5.5e-12 over 560 apexes of that range with c = 0


@given(
    height=st.floats(1.0, 1.1),
    speed=st.floats(3.5, 5.0),
    angle=st.floats(0.35, 0.45),
    damping=st.floats(0.0, 0.2),
)
def test_damped_hop_never_gains_energy(height, speed, angle, damping):
    """Over an apex return of the exact damped map (liftoff "force"; the flights and g_s = g_f
    conserve energy), the next apex's energy is at most the apex's: the damper takes c q_rd^2 and
    the spring's energy left at a liftoff below l0 stays in the massless leg. In that range every
    hop is OK up to 20 % of critical damping (measured over a grid of 560)."""
    p = HUMAN_RUNNER.with_(c=damping * critical(HUMAN_RUNNER))
    res = slipmaps.apex_return("exact", p, apex_height=height, apex_speed=speed, touchdown_angle=angle)
    assert res.status == Status.OK
    before = p.m * (p.g_f * height + 0.5 * speed**2)
    after = p.m * (p.g_f * res.values["next_apex_height"] + 0.5 * res.values["next_apex_speed"] ** 2)
    assert after <= before * (1.0 + E_ROUNDOFF), (after - before) / before


def test_a_map_without_c_refuses_damping_in_one_line():
    damped = HUMAN_RUNNER.with_(c=50.0)
    takers = [m.name for m in (*slipmaps.maps(), *index.halves()) if "c" in m.params]
    assert takers == [
        "geyer-damped",
        "iterative",
        "exact",
        "exact-compression",
        "exact-decompression",
        "iterative-compression",
        "iterative-decompression",
    ]
    apex = {"apex_height": 1.0, "apex_speed": 5.0, "touchdown_angle": 0.35}
    calls = [
        lambda: slipmaps.apex_return("geyer", damped, **apex),
        lambda: slipmaps.apex_return_batch("iterative-report", damped, **apex),
        lambda: slipmaps.stance("gravity-type2", damped, TOUCHDOWN),
        lambda: slipmaps.stance_jacobian("geyer", damped, TOUCHDOWN),
        lambda: slipmaps.half_stance("iterative-report-compression", damped, TOUCHDOWN),
    ]
    for call in calls:
        with pytest.raises(ValueError) as err:
            call()
        message = str(err.value)
        assert "\n" not in message and "does not model c" in message and "c=50.0" in message
        assert message.endswith("maps that take c: " + ", ".join(takers)), message
    for name in ("geyer", "iterative"):  # c = 0 (the default) is every map's
        assert slipmaps.apex_return(name, HUMAN_RUNNER.with_(c=0.0), **apex).status == Status.OK
    with pytest.raises(ValueError, match="method='scipy'.* does not model the leg damping c"):
        slipmaps.stance("exact", damped, TOUCHDOWN, method="scipy")
    with pytest.raises(ValueError, match="c must be finite and non-negative"):
        HUMAN_RUNNER.with_(c=-1.0)


def test_cli_and_scenarios_refuse_damping_for_a_map_without_it(tmp_path, capsys):
    assert main(["compare", "--no-plot", "--map", "geyer", "--c", "50"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("slipmaps compare: error: map 'geyer' does not model c") and err.count("\n") == 1
    scenario = tmp_path / "damped.toml"
    scenario.write_text('steps = 1\nmodel = "iterative-report"\nplant = "exact"\n[params]\nc = 50.0\n')
    assert main(["run", str(scenario), "--no-figure"]) == 2
    err = capsys.readouterr().err
    assert "map 'iterative-report' does not model c" in err
    assert "Traceback" not in err and err.count("\n") == 1


# ----------------------------------------------------------------------------------------------
# Gaits: with damping k_d > k_c puts back what the leg loses
# ----------------------------------------------------------------------------------------------
def test_a_damped_gait_needs_k_d_above_k_c_and_the_deadbeat_finds_it():
    """At 10 % of the critical damping (253 N s/m, the human runner) the deadbeat step on the exact
    map finds the periodic gait through (1 m, 5 m/s) with the touchdown angle and k_d (measured:
    k_d = 37.3 kN/m against k_c = 20 kN/m, 0.347 rad); the exact map from that plan returns to the
    same apex; with k_d held at k_c the angle keeps the speed and the apex falls."""
    damped = HUMAN_RUNNER.with_(c=253.0)
    plan = slipmaps.deadbeat("exact", damped, 1.0, 5.0, 1.0, 5.0, controls=("touchdown_angle", "k_d"))
    assert plan.status.name == "REACHED", plan
    assert plan.k_d > 1.5 * damped.k_c, plan
    step = slipmaps.apex_return("exact", damped.with_(k_d=plan.k_d), 1.0, 5.0, plan.touchdown_angle)
    assert step.status == Status.OK
    assert abs(step.next_apex_height - 1.0) < 1e-8 and abs(step.next_apex_speed - 5.0) < 1e-8, step
    # the angle alone (one control, two targets: the speed first) keeps 5 m/s and loses height
    held = slipmaps.deadbeat("exact", damped, 1.0, 5.0, 1.0, 5.0, controls=("touchdown_angle",))
    assert held.k_d == damped.k_c and abs(held.next_apex_speed - 5.0) < 1e-8, held
    assert held.next_apex_height < 0.95, held  # measured 0.904 m: the energy the leg lost


def test_fixed_points_refuse_a_damped_leg_and_name_the_deadbeat():
    """fixed_points searches the line of constant apex energy: a damped step leaves it, so it says
    so in one line (it returned a point 0.44 m/s off the apex speed as OK before it checked c)."""
    with pytest.raises(ValueError, match=r"c == 0.*slipmaps.deadbeat") as info:
        slipmaps.fixed_points("exact", HUMAN_RUNNER.with_(c=253.0), apex_height=1.0, speed=5.0)
    assert "\n" not in str(info.value)
