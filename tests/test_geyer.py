"""Geyer et al.'s approximate stance map (report section 3.1, map ``"geyer"``): its own consistency,
its closed forms and its exact parts, through the public API.

* Eq (20): at q_r_td = q_r_lo = l0 the approximate stance is symmetric about the bottom.
* Eqs (25)-(26): the stance and bottom times in touchdown states; the printed arctan form of (26)
  has the wrong branch for slow gaits (q_thd_td^2 l0 < g_s), the generated kernel uses atan2.
* Eqs (9)-(19): the map's events and trajectory are the solution of its own approximated dynamics
  (Assumptions 1-2), integrated here with solve_ivp.
* The apex-return map is the exact descent (section 2.1), the stance map and the exact ascent.
* The vertical hop (apex speed 0, leg vertical) is a valid gait, for the map and the exact simulator.

The accuracy against the exact stance is measured on grids by ``slipmaps accuracy``
(docs/accuracy.json), not here; the README's default case is pinned at the end. Every tolerance is
about 10x the error measured over the states of its test (the measurement is in a comment next to
it). Equation numbers are the report's.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
import slipmaps
from scipy.integrate import solve_ivp
from slipmaps import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams, Status
from slipmaps.generated import flight as g_flight
from slipmaps.runtime.exact.reference import simulate_step

MAP = "geyer"
PARAMS = [pytest.param(HUMAN_RUNNER, id="human"), pytest.param(ROBOT_HOPPER, id="hopper")]


def _random_touchdowns(params: SlipParams, n: int, seed: int) -> np.ndarray:
    """Touchdown states at q_r = l0 with Froude-scaled rates: q_rd in -(0.05..1) sqrt(g l0),
    q_th in 0.05..0.6 rad, q_thd in -(0.3..2.5) sqrt(g/l0) (a quarter of them slow:
    q_thd^2 l0 < g_s)."""
    rng = np.random.default_rng(seed)
    vs, ws = math.sqrt(params.g_s * params.l0), math.sqrt(params.g_s / params.l0)
    return np.column_stack(
        [
            np.full(n, params.l0),
            -rng.uniform(0.05, 1.0, n) * vs,
            rng.uniform(0.05, 0.6, n),
            -rng.uniform(0.3, 2.5, n) * ws,
        ]
    )


def _omega0_hat(params: SlipParams, q_thd: np.ndarray) -> np.ndarray:
    """omega0_hat of (9)-(11) at a touchdown with q_r = l0: sqrt(k/m + 3 q_thd^2)."""
    return np.sqrt(params.k / params.m + 3.0 * q_thd**2)


# ----------------------------------------------------------------------------------------------
# 1. Symmetry at q_r_td = q_r_lo = l0 (eqs 15, 16, 19, 20)
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("params", PARAMS)
def test_eq20_stance_is_symmetric_at_rest_length(params):
    """Liftoff mirrors touchdown to round-off (q_rd_lo = -q_rd_td, q_thd_lo = q_thd_td, t_b = t_s/2,
    a sweep symmetric about the bottom) and t_s = [pi + 2 arcsin(-a/b)] / omega0_hat, eq (20)."""
    assert params.q_r_td == params.q_r_lo == params.l0
    td = _random_touchdowns(params, 200, seed=20)
    res = slipmaps.stance_batch(MAP, params, td)
    assert res.ok.all(), res.counts()  # measured: all 200 states are OK for both parameter sets
    _, q_rd, q_th, q_thd = td.T
    lo, bot = res["liftoff"], res["bottom"]
    t_s, t_b = res["t_stance"], res["t_bottom"]
    # Measured over these states (both parameter sets), relative: q_rd 4.7e-14, q_thd 4.9e-16,
    # t_b - t_s/2 3.6e-16, sweep symmetry 6.4e-15, eq (20) 4.8e-14.
    assert np.all(lo[:, 0] == params.l0) and np.all(bot[:, 1] == 0.0)
    np.testing.assert_allclose(lo[:, 1], -q_rd, rtol=1e-12, atol=0)
    np.testing.assert_allclose(lo[:, 3], q_thd, rtol=1e-14, atol=0)
    np.testing.assert_allclose(t_b, t_s / 2.0, rtol=4e-15, atol=0)
    # The sweep is symmetric about the bottom: q_th_lo - q_th_b = q_th_b - q_th_td (eq 19).
    np.testing.assert_allclose(lo[:, 2] - bot[:, 2], bot[:, 2] - q_th, rtol=1e-13, atol=0)
    # Eq (20) with a and b of (11) at rho_td = 0, where epsilon of (8) leaves b^2 = a^2 + (q_rd/l0)^2/w^2.
    l0, g = params.l0, params.g_s
    w = _omega0_hat(params, q_thd)
    a = (q_thd**2 - g / l0) / w**2
    b = np.sqrt(a**2 + (q_rd / l0) ** 2 / w**2)
    np.testing.assert_allclose(t_s, (math.pi + 2.0 * np.arcsin(-a / b)) / w, rtol=1e-12, atol=0)


# ----------------------------------------------------------------------------------------------
# 2. The times in touchdown states (eqs 25, 26)
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("params", PARAMS)
def test_eq25_stance_time_in_touchdown_states(params):
    """Corrected (25): t_s = [pi + 2 arctan((g_s - l0 q_thd^2)/(|q_rd| w))] / w, w^2 = k/m + 3 q_thd^2."""
    td = _random_touchdowns(params, 100, seed=25)
    res = slipmaps.stance_batch(MAP, params, td)
    assert res.ok.all(), res.counts()  # measured: all 100 OK
    _, q_rd, _, q_thd = td.T
    w = _omega0_hat(params, q_thd)
    t_s = (math.pi + 2.0 * np.arctan((params.g_s - params.l0 * q_thd**2) / (np.abs(q_rd) * w))) / w
    np.testing.assert_allclose(res["t_stance"], t_s, rtol=1e-12, atol=0)  # measured 1.2e-13 relative
    assert np.all((0.0 < res["t_stance"]) & (res["t_stance"] < 2.0 * math.pi / w))  # measured <= 0.90


@pytest.mark.parametrize("params", PARAMS)
def test_eq26_bottom_time_in_touchdown_states(params):
    """Corrected (26): t_b = atan2(|q_rd| w, q_thd^2 l0 - g_s) / w, on both branches (some states
    are slow, q_thd^2 l0 < g_s, where the printed arctan form is negative)."""
    td = _random_touchdowns(params, 100, seed=26)
    res = slipmaps.stance_batch(MAP, params, td)
    assert res.ok.all(), res.counts()
    _, q_rd, _, q_thd = td.T
    slow = q_thd**2 * params.l0 < params.g_s
    assert 10 <= slow.sum() <= 90  # both branches are exercised (measured: 30 slow)
    w = _omega0_hat(params, q_thd)
    t_b = np.arctan2(np.abs(q_rd) * w, q_thd**2 * params.l0 - params.g_s) / w
    np.testing.assert_allclose(res["t_bottom"], t_b, rtol=1e-12, atol=0)  # measured 6.4e-14 relative
    assert np.all((0.0 < res["t_bottom"]) & (res["t_bottom"] < res["t_stance"]))


def test_eq26_printed_arctan_branch_is_wrong_for_slow_gaits():
    """Slow hopper (q_thd_td^2 l0 < g_s): the printed arctan form of (26) is negative; the corrected
    t_b = atan2(|q_rd| w, q_thd^2 l0 - g_s)/w, w = sqrt(k/m + 3 q_thd^2), is what the map returns."""
    p = ROBOT_HOPPER
    ex = simulate_step(p, 1.05 * p.l0, 1.0, 0.3)  # 1 m/s, touchdown angle 0.3 rad
    assert ex.ok, ex.message
    q_r, q_rd, q_th, q_thd = ex.touchdown
    assert q_r == p.l0 and q_rd < 0.0
    assert q_thd**2 * p.l0 < p.g_s  # measured: 2.27 < 9.81 m/s^2, the slow branch
    res = slipmaps.stance(MAP, p, ex.touchdown)
    assert res.ok, res.message
    w = math.sqrt(p.k / p.m + 3.0 * q_thd**2)
    corrected = math.atan2(abs(q_rd) * w, q_thd**2 * p.l0 - p.g_s) / w
    printed = math.atan(abs(q_rd) * w / (q_thd**2 * p.l0 - p.g_s)) / w
    assert printed < 0.0  # measured: -0.0539 s
    assert 0.0 < res.t_bottom < res.t_stance
    assert res.t_bottom == pytest.approx(corrected, rel=1e-14, abs=0)  # measured: 1.7e-16 relative
    assert res.t_bottom == pytest.approx(res.t_stance / 2.0, rel=2e-15, abs=0)  # measured 1.7e-16
    # ... and the corrected branch is physical: 0.0829 s vs the exact 0.0834 s (-0.58 %).
    assert res.t_bottom == pytest.approx(ex.t_bottom, rel=0.01)


# ----------------------------------------------------------------------------------------------
# 3. The map solves its own approximated dynamics (Assumptions 1-2, eqs 8-11, 13-14, 17-19)
# ----------------------------------------------------------------------------------------------
POLAR = ("q_r", "q_rd", "q_th", "q_thd")


def _integrate_approximate_dynamics(
    params: SlipParams, td
) -> tuple[dict[str, float], Callable[[float], np.ndarray]]:
    """Integrate the dynamics the map is built on with solve_ivp: its events and its dense state.

    Assumption 2 turns (8) into rho_d^2 = lambda rho^2 + mu rho + nu (9), i.e. rho_dd =
    omega^2 (1 - 3 rho) - omega0^2 rho - g_s/l0; the leg angle follows the linearized (18),
    q_thd = omega (1 - 2 rho); the leg-angle rate reported is (17), omega/(1 + rho)^2. As in the map,
    epsilon is the energy (8) of the approximated system (Taylor polynomial of 1/(1 + rho)^2) at
    touchdown, so (9) passes through the touchdown state: the start is (rho_td, q_rd_td / l0).
    Returns the events (by output name) and state(t) -> (q_r, q_rd, q_th, q_thd).
    """
    l0, g, w0s = params.l0, params.g_s, params.k / params.m
    q_r, q_rd, q_th, q_thd = td
    om = q_r**2 * q_thd / l0**2
    rho = q_r / l0 - 1.0
    taylor = 1.0 - 2.0 * rho + 3.0 * rho**2
    eps = (q_rd / l0) ** 2 + om**2 * taylor + w0s * rho**2 + 2.0 * g / l0 * (1.0 + rho)
    lam, mu, nu = -(3.0 * om**2 + w0s), 2.0 * (om**2 - g / l0), eps - om**2 - 2.0 * g / l0
    rhod = -math.sqrt(lam * rho**2 + mu * rho + nu)
    # The quadratic (9) passes through touchdown (measured 2.2e-15 relative).
    assert rhod == pytest.approx(q_rd / l0, rel=1e-13)

    def f(_t, y):
        return [y[1], om**2 * (1.0 - 3.0 * y[0]) - w0s * y[0] - g / l0, om * (1.0 - 2.0 * y[0])]

    def bottom(_t, y):
        return y[1]

    def liftoff(_t, y):
        return y[0] - (params.q_r_lo / l0 - 1.0)

    for ev in (bottom, liftoff):
        ev.terminal, ev.direction = True, 1.0
    opts = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-14, "dense_output": True}
    s1 = solve_ivp(f, (0.0, 10.0), [rho, rhod, q_th], events=bottom, **opts)
    t_b, y_b = s1.t_events[0][0], s1.y_events[0][0]
    s2 = solve_ivp(f, (t_b, 10.0), y_b, events=liftoff, **opts)
    t_s, y_l = s2.t_events[0][0], s2.y_events[0][0]

    def polar(y) -> np.ndarray:
        return np.array([l0 * (1.0 + y[0]), l0 * y[1], y[2], om / (1.0 + y[0]) ** 2])

    events = {"t_bottom": t_b, "t_stance": t_s}
    events.update({f"bottom_{n}": v for n, v in zip(POLAR, polar(y_b), strict=True)})
    events.update({f"liftoff_{n}": v for n, v in zip(POLAR, polar(y_l), strict=True)})
    events["bottom_q_rd"] = 0.0
    return events, lambda t: polar(s1.sol(t) if t <= t_b else s2.sol(t))


#: Bounds (SI units) by kind, about 10x the errors measured over the cases below (DOP853 with rtol
#: 1e-12): events: times 4.3e-14 s, lengths 8.9e-14 m, angles 2.3e-13 rad, rates 2.0e-12;
#: trajectory: lengths 2.4e-13 m, angles 1.2e-13 rad, rates 7.7e-12.
TOL = {"t": 5e-13, "q_r": 3e-12, "q_th": 3e-12, "q_rd": 1e-10, "q_thd": 1e-10}


@pytest.mark.parametrize(
    ("params", "td"),
    [
        pytest.param(HUMAN_RUNNER, (1.0, -1.5, 0.35, -4.5), id="human-symmetric"),
        pytest.param(
            HUMAN_RUNNER.with_(q_r_td=0.97, q_r_lo=0.95), (0.97, -1.2, 0.3, -5.0), id="human-nonsym"
        ),
        pytest.param(ROBOT_HOPPER, (0.25, -0.8, 0.45, -8.0), id="hopper-symmetric"),
        pytest.param(ROBOT_HOPPER.with_(q_r_lo=0.24), (0.25, -0.8, 0.45, -3.0), id="hopper-slow-lo"),
        pytest.param(ROBOT_HOPPER.with_(q_r_td=0.23), (0.23, -0.8, 0.45, -8.0), id="hopper-td"),
    ],
)
def test_eq9_eq19_map_solves_its_approximated_dynamics(params, td):
    res = slipmaps.stance(MAP, params, td)
    assert res.ok, res.message
    events, state = _integrate_approximate_dynamics(params, td)
    for name, value in events.items():
        kind = "t" if name.startswith("t_") else name.split("_", 1)[1]
        assert res[name] == pytest.approx(value, rel=0, abs=TOL[kind]), name
    t, states, status = slipmaps.trajectory(MAP, params, td)
    assert status == Status.OK and t.shape == (200,) and t[-1] == res.t_stance
    ref = np.array([state(x) for x in t])
    for j, name in enumerate(POLAR):
        np.testing.assert_allclose(states[:, j], ref[:, j], rtol=0, atol=TOL[name], err_msg=name)


# ----------------------------------------------------------------------------------------------
# 4. The apex-return map: exact descent, the stance map, exact ascent
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "params", [*PARAMS, pytest.param(HUMAN_RUNNER.with_(q_r_td=0.97, q_r_lo=0.95), id="nonsym")]
)
def test_apex_return_is_exact_descent_stance_map_exact_ascent(params):
    """Over apex heights, speeds (0 to 2 sqrt(g l0)) and touchdown angles (0 to 0.5 rad): the map
    flies to the exact simulator's touchdown (the same descent), its stance is the stance map's
    from that touchdown and its next apex the exact ascent from that liftoff, bit for bit; a
    failing stage's status is the map's."""
    n_ok, statuses = 0, set()
    for height in params.l0 * np.array([0.95, 1.0, 1.1, 1.3]):
        for speed in math.sqrt(params.g_s * params.l0) * np.array([0.0, 0.5, 1.0, 1.5, 2.0]):
            for angle in (0.0, 0.2, 0.35, 0.5):
                res = slipmaps.apex_return(MAP, params, height, speed, angle)
                ex = simulate_step(params, height, speed, angle)
                statuses.add(res.status)
                if ex.touchdown is None:  # no touchdown: the descent failed, for both
                    assert res.status == ex.status == Status.APEX_TOO_LOW
                    continue
                st = slipmaps.stance(MAP, params, ex.touchdown)
                if not st.ok:
                    assert res.status == st.status
                    continue
                direction = float(np.sign(speed))  # the step's: 0 for a hop in place
                *apex, t_ascent, _, _, code = g_flight.liftoff_to_apex(*st.liftoff, params.g_f, direction)
                assert res.status == code
                if code != Status.OK:
                    continue
                n_ok += 1
                assert res.t_descent == ex.t_descent and res.t_stance == st.t_stance
                assert res.liftoff == st.liftoff
                assert (res.next_apex_height, res.next_apex_speed, res.t_ascent) == (*apex, t_ascent)
    # Measured: 38, 29 and 43 of the 80 steps OK; the others APEX_TOO_LOW (no touchdown from the
    # lowest apexes), LIFTOFF_DOWNWARD / LIFTOFF_BACKWARD (too steep or too shallow a leg), NO_LIFTOFF.
    assert n_ok >= 25
    assert {Status.APEX_TOO_LOW, Status.LIFTOFF_DOWNWARD, Status.LIFTOFF_BACKWARD} <= statuses


# ----------------------------------------------------------------------------------------------
# 5. The vertical hop
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("params", PARAMS)
@pytest.mark.parametrize("height", [1.02, 1.2, 1.5], ids=lambda h: f"{h}l0")
def test_vertical_hop_is_a_valid_gait(params, height):
    """Apex speed 0, leg vertical at touchdown: a hop in place. Geyer's map and the exact simulator
    both lift off vertically (not LIFTOFF_BACKWARD) and return to the same apex, at speed 0."""
    h = height * params.l0
    for name, rel in ((MAP, 1e-14), ("exact", 1e-10)):
        res = slipmaps.apex_return(name, params, h, 0.0, 0.0)
        assert res.status == Status.OK, (name, res.message)
        assert abs(res.next_apex_speed) <= 1e-12, name  # measured: exactly 0 (-0.0) for both
        # Measured relative apex height errors: Geyer 1.9e-16 (the symmetric stance conserves the
        # energy), exact 1.1e-11 (integration, rtol 1e-11).
        assert res.next_apex_height == pytest.approx(h, rel=rel), name
        assert res.liftoff[2] == 0.0 and res.liftoff[3] == 0.0, name


# ----------------------------------------------------------------------------------------------
# 6. The README's default case
# ----------------------------------------------------------------------------------------------
def test_readme_default_case_errors():
    """The quick start's table (docs/getting_started.md; human runner, apex 1 m at 5 m/s, leg at
    0.35 rad): Geyer's map minus the exact stance, both from the same exact touchdown, to half a unit
    of the table's third digit."""
    geyer = slipmaps.apex_return(MAP, HUMAN_RUNNER, 1.0, 5.0, 0.35)
    exact = slipmaps.apex_return("exact", HUMAN_RUNNER, 1.0, 5.0, 0.35)
    assert geyer.ok and exact.ok
    assert geyer.t_descent == exact.t_descent
    readme = {
        "t_stance": 1.40e-3,
        "liftoff_q_rd": -3.26e-2,
        "liftoff_q_th": -4.13e-4,
        "liftoff_q_thd": 6.73e-2,
        "next_apex_height": -3.08e-4,
        "next_apex_speed": -7.46e-2,
    }
    for name, err in readme.items():
        half_digit = 0.5 * 10.0 ** (math.floor(math.log10(abs(err))) - 2)
        assert geyer[name] - exact[name] == pytest.approx(err, rel=0, abs=half_digit), name
