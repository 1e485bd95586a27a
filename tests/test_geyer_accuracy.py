"""Geyer et al.'s approximate stance map (report section 3.1) against the exact stance, and its
own internal consistency.

* Accuracy on the grid of :mod:`slipmaps.runtime.accuracy` (the same grid as docs/accuracy.md):
  every error bound is 1.5x the error measured on that grid (the measurement is in the comment
  next to each bound). A bound that fails is a change in the map or the simulator to look at, not
  a tolerance to widen.
* Eq (20): at q_r_td = q_r_lo = l0 the approximate stance is exactly symmetric about the bottom.
* Eqs (25)-(26): the stance and bottom times in touchdown states; the printed arctan form of (26)
  has the wrong branch for slow gaits (q_thd_td^2 l0 < g_s), the generated kernel uses atan2.
* Eqs (9)-(19): the map is the exact solution of its own approximated dynamics (Assumptions 1-2).
* The parallel batch kernels give bit-identical results to the scalar kernels.

Equation numbers are the report's; Status codes are slipmaps.generated.status.Status.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from slipmaps.generated.status import Status
from slipmaps.runtime.accuracy import GRID, QUANTITIES, measure_grid, summarize
from slipmaps.runtime.apex_maps import APEX_COLUMNS, apex_return_geyer, apex_return_geyer_batch
from slipmaps.runtime.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from slipmaps.runtime.simulate import simulate_stance, simulate_step
from slipmaps.runtime.stance_maps import STANCE_COLUMNS, geyer_stance, geyer_stance_batch

GRIDS = {spec.name: spec for spec in GRID}

#: Error bounds (approx - exact, SI units) on the accuracy grid: (max abs, median abs) per quantity,
#: each 1.5x the value measured with the default integrator tolerances (rtol 1e-11), given in the
#: comment as (measured max, measured median).
BOUNDS = {
    "human runner": {
        "t_stance": (8.5e-3, 3.5e-3),  # 5.68e-3 s, 2.34e-3 s
        "t_bottom": (4.2e-3, 1.4e-3),  # 2.81e-3 s, 9.39e-4 s
        "b_q_r": (9.6e-3, 2.8e-3),  # 6.43e-3 m, 1.89e-3 m
        "b_q_th": (2.1e-2, 2.1e-3),  # 1.40e-2 rad, 1.43e-3 rad
        "lo_q_rd": (0.21, 6.5e-2),  # 0.140 m/s, 4.36e-2 m/s
        "lo_q_th": (8.5e-2, 4.4e-3),  # 5.64e-2 rad, 2.90e-3 rad
        "lo_q_thd": (0.75, 0.12),  # 0.500 rad/s, 8.29e-2 rad/s
        "apex_height": (4.7e-2, 4.1e-3),  # 3.16e-2 m, 2.70e-3 m
        "apex_speed": (1.0, 0.14),  # 0.664 m/s, 9.13e-2 m/s
    },
    "robot hopper": {
        "t_stance": (1.6e-2, 8.0e-3),  # 1.08e-2 s, 5.31e-3 s
        "t_bottom": (7.8e-3, 3.6e-3),  # 5.17e-3 s, 2.42e-3 s
        "b_q_r": (1.0e-2, 3.5e-3),  # 6.63e-3 m, 2.31e-3 m
        "b_q_th": (4.1e-2, 8.5e-3),  # 2.75e-2 rad, 5.64e-3 rad
        "lo_q_rd": (0.19, 8.8e-2),  # 0.129 m/s, 5.89e-2 m/s
        "lo_q_th": (0.18, 2.5e-2),  # 0.121 rad, 1.68e-2 rad
        "lo_q_thd": (2.1, 0.42),  # 1.39 rad/s, 0.283 rad/s
        "apex_height": (3.1e-2, 5.4e-3),  # 2.09e-2 m, 3.58e-3 m
        "apex_speed": (0.81, 0.14),  # 0.540 m/s, 9.54e-2 m/s
    },
}

#: Grid points where both sides complete the step, as measured (of 81 each); the rest fail with
#: LIFTOFF_DOWNWARD / LIFTOFF_BACKWARD (the body vaults over a steep leg, or stops).
MIN_COMPARED = {"human runner": 75, "robot hopper": 63}


@pytest.fixture(scope="module")
def grid_records() -> dict:
    return {name: measure_grid(spec) for name, spec in GRIDS.items()}


# ----------------------------------------------------------------------------------------------
# 1. Accuracy against the exact stance on the grid (eqs 7-20, the corrected 23-26)
# ----------------------------------------------------------------------------------------------
def test_bounds_cover_every_quantity():
    for bounds in BOUNDS.values():
        assert set(bounds) == {q.key for q in QUANTITIES}


@pytest.mark.parametrize("name", list(GRIDS))
def test_eq7_eq20_geyer_map_accuracy_on_grid(grid_records, name):
    records = grid_records[name]
    assert len(records) == GRIDS[name].size == 81
    stats = summarize(records)
    failures = []
    for key, (max_bound, median_bound) in BOUNDS[name].items():
        s = stats[key]
        assert s.n >= MIN_COMPARED[name]
        if not s.max_abs <= max_bound:
            failures.append(f"{key}: max abs error {s.max_abs:.3g} > {max_bound:.3g} at {s.worst}")
        if not s.median_abs <= median_bound:
            failures.append(f"{key}: median abs error {s.median_abs:.3g} > {median_bound:.3g}")
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("name", list(GRIDS))
def test_eq7_eq20_grid_failures_are_only_liftoff_direction(grid_records, name):
    records = grid_records[name]
    assert sum(r.ok for r in records) >= MIN_COMPARED[name]
    allowed = {Status.OK, Status.LIFTOFF_DOWNWARD, Status.LIFTOFF_BACKWARD}
    for r in records:
        assert r.exact_status in allowed, (r.apex_speed, r.q_th_td, r.exact_status)
        assert r.approx_status in allowed, (r.apex_speed, r.q_th_td, r.approx_status)
        # Every grid point touches down and both stances reach liftoff; only the flight can fail.
        assert r.touchdown is not None
        assert math.isfinite(r.exact["t_stance"]) and math.isfinite(r.approx["t_stance"])


@pytest.mark.parametrize("name", list(GRIDS))
def test_eq12_eq14_apex_return_map_reuses_exact_touchdown_and_stance_map(grid_records, name):
    """apex_return_geyer flies to the same touchdown state as simulate_step (same flight kernel),
    so its stance is bit for bit the stance map's from the exact touchdown."""
    spec = GRIDS[name]
    for r in grid_records[name][::7]:
        if not r.ok:
            continue
        ar = apex_return_geyer(spec.params, r.apex_height, r.apex_speed, r.q_th_td)
        st = geyer_stance(spec.params, r.touchdown)
        assert ar.liftoff == st.liftoff
        assert ar.t_stance == st.t_stance
        ex = simulate_step(spec.params, r.apex_height, r.apex_speed, r.q_th_td)
        assert ex.touchdown == r.touchdown
        assert ex.t_stance == r.exact["t_stance"] and ex.next_apex[1] == r.exact["apex_speed"]


# ----------------------------------------------------------------------------------------------
# 2. Symmetry at q_r_td = q_r_lo = l0 (eqs 15, 16, 20) and the times in touchdown states (25, 26)
# ----------------------------------------------------------------------------------------------
def _random_touchdowns(params: SlipParams, n: int, seed: int) -> np.ndarray:
    """Touchdown states at q_r = l0 with Froude-scaled rates: q_rd in -(0.05..1) sqrt(g l0),
    q_th in 0.05..0.6 rad, q_thd in -(0.3..2.5) sqrt(g/l0)."""
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


def _eq11_a_b_omega0_hat(params: SlipParams, q_rd: float, q_thd: float) -> tuple[float, float, float]:
    """a, b, omega0_hat of eq (11) at a touchdown with q_r = l0 (omega = q_thd, epsilon from (8))."""
    l0, g = params.l0, params.g_s
    w2 = params.k / params.m + 3.0 * q_thd**2
    a = (q_thd**2 - g / l0) / w2
    eps = (q_rd / l0) ** 2 + q_thd**2 + 2.0 * g / l0  # eq (8) at rho = 0
    b = math.sqrt(a**2 + (eps - q_thd**2 - 2.0 * g / l0) / w2)
    return a, b, math.sqrt(w2)


@pytest.mark.parametrize("params", [HUMAN_RUNNER, ROBOT_HOPPER], ids=["human", "hopper"])
def test_eq20_stance_is_symmetric_at_rest_length(params):
    assert params.q_r_td == params.q_r_lo == params.l0
    n_ok = 0
    for td in _random_touchdowns(params, 200, seed=20):
        res = geyer_stance(params, td)
        if not res.ok:
            continue
        n_ok += 1
        q_r, q_rd, q_th, q_thd = td
        t_s, t_b = res.t_stance, res.t_bottom
        lo, bot = res.liftoff, res.bottom
        # Measured over these states (both parameter sets), relative: q_rd 1.1e-13, q_thd 0,
        # t_b - t_s/2 0, sweep symmetry 7.5e-15, eq (20) 8.8e-14.
        assert lo[0] == params.l0
        assert lo[1] == pytest.approx(-q_rd, rel=1e-12, abs=0)
        assert lo[3] == pytest.approx(q_thd, rel=1e-12, abs=0)
        assert t_b == pytest.approx(t_s / 2.0, rel=1e-12, abs=0)
        assert bot[1] == 0.0
        # The sweep is symmetric about the bottom: q_th_lo - q_th_b = q_th_b - q_th_td (eq 19).
        assert lo[2] - bot[2] == pytest.approx(bot[2] - q_th, rel=1e-11, abs=1e-14)
        # Eq (20): t_s = [pi + 2 arcsin(-a/b)] / omega0_hat, with a, b from (11).
        a, b, w = _eq11_a_b_omega0_hat(params, q_rd, q_thd)
        assert t_s == pytest.approx((math.pi + 2.0 * math.asin(-a / b)) / w, rel=1e-12, abs=0)
    assert n_ok >= 190  # measured: all 200 states are OK for both parameter sets


@pytest.mark.parametrize("params", [HUMAN_RUNNER, ROBOT_HOPPER], ids=["human", "hopper"])
def test_eq25_stance_time_in_touchdown_states(params):
    """Corrected (25): t_s = [pi + 2 arctan((g_s - l0 q_thd^2)/(|q_rd| w))]/w, w^2 = k/m + 3 q_thd^2."""
    l0, g = params.l0, params.g_s
    for td in _random_touchdowns(params, 100, seed=25):
        res = geyer_stance(params, td)
        if not res.ok:
            continue
        _, q_rd, _, q_thd = td
        w = math.sqrt(params.k / params.m + 3.0 * q_thd**2)
        t_s = (math.pi + 2.0 * math.atan((g - l0 * q_thd**2) / (abs(q_rd) * w))) / w
        assert res.t_stance == pytest.approx(t_s, rel=1e-12, abs=0)  # measured <= 1.3e-13 relative
        assert 0.0 < res.t_stance < 2.0 * math.pi / w


def test_eq26_branch():
    """Slow hopper (q_thd_td^2 l0 < g_s): the printed arctan form of (26) is negative; the corrected
    t_b = atan2(|q_rd| w, q_thd^2 l0 - g_s)/w, w = sqrt(k/m + 3 q_thd^2), is what the kernel returns."""
    p = ROBOT_HOPPER
    ex = simulate_step(p, 1.05 * p.l0, 1.0, 0.3)  # 1 m/s, touchdown angle 0.3 rad
    assert ex.ok, ex.message
    q_r, q_rd, q_th, q_thd = ex.touchdown
    assert q_r == p.l0 and q_rd < 0.0
    assert q_thd**2 * p.l0 < p.g_s  # measured: 2.27 < 9.81 m/s^2, the slow branch
    res = geyer_stance(p, ex.touchdown)
    assert res.ok, res.message
    w = math.sqrt(p.k / p.m + 3.0 * q_thd**2)
    corrected = math.atan2(abs(q_rd) * w, q_thd**2 * p.l0 - p.g_s) / w
    printed = math.atan(abs(q_rd) * w / (q_thd**2 * p.l0 - p.g_s)) / w
    assert printed < 0.0  # measured: -0.0539 s
    assert 0.0 < res.t_bottom < res.t_stance
    assert res.t_bottom == pytest.approx(corrected, rel=1e-12, abs=0)  # measured: 1.7e-16 relative
    assert res.t_bottom == pytest.approx(res.t_stance / 2.0, rel=1e-12, abs=0)
    # ... and the corrected branch is physical: 0.0829 s vs the exact 0.0834 s (-0.58 %).
    assert res.t_bottom == pytest.approx(ex.t_bottom, rel=0.01)


# ----------------------------------------------------------------------------------------------
# 3. The map solves its own approximated dynamics (Assumptions 1-2, eqs 8-11, 13-14, 17-19)
# ----------------------------------------------------------------------------------------------
def _integrate_approximate_dynamics(params: SlipParams, td) -> dict[str, float]:
    """Integrate the dynamics the map is built on with solve_ivp and return its events.

    Assumption 2 turns (8) into rho_d^2 = lambda rho^2 + mu rho + nu (9), i.e. rho_dd =
    omega^2 (1 - 3 rho) - omega0^2 rho - g_s/l0; the leg angle follows the linearized (18),
    q_thd = omega (1 - 2 rho); the leg-angle rate reported is (17), omega/(1 + rho)^2. As in the map,
    epsilon is the energy (8) of the approximated system (Taylor polynomial of 1/(1 + rho)^2) at
    touchdown, so (9) passes through the touchdown state: the start is (rho_td, q_rd_td / l0).
    """
    l0, g, w0s = params.l0, params.g_s, params.k / params.m
    q_r, q_rd, q_th, q_thd = td
    om = q_r**2 * q_thd / l0**2
    rho = q_r / l0 - 1.0
    taylor = 1.0 - 2.0 * rho + 3.0 * rho**2
    eps = (q_rd / l0) ** 2 + om**2 * taylor + w0s * rho**2 + 2.0 * g / l0 * (1.0 + rho)
    lam, mu, nu = -(3.0 * om**2 + w0s), 2.0 * (om**2 - g / l0), eps - om**2 - 2.0 * g / l0
    rhod = -math.sqrt(lam * rho**2 + mu * rho + nu)
    assert rhod == pytest.approx(q_rd / l0, rel=1e-12)  # the quadratic passes through touchdown

    def f(_t, y):
        return [y[1], om**2 * (1.0 - 3.0 * y[0]) - w0s * y[0] - g / l0, om * (1.0 - 2.0 * y[0])]

    def bottom(_t, y):
        return y[1]

    def liftoff(_t, y):
        return y[0] - (params.q_r_lo / l0 - 1.0)

    for ev, direction in ((bottom, 1.0), (liftoff, 1.0)):
        ev.terminal, ev.direction = True, direction
    opts = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-14}
    s1 = solve_ivp(f, (0.0, 10.0), [rho, rhod, q_th], events=bottom, **opts)
    t_b, y_b = s1.t_events[0][0], s1.y_events[0][0]
    s2 = solve_ivp(f, (t_b, 10.0), y_b, events=liftoff, **opts)
    t_s, y_l = s2.t_events[0][0], s2.y_events[0][0]
    return {
        "t_bottom": t_b,
        "t_stance": t_s,
        "b_q_r": l0 * (1.0 + y_b[0]),
        "b_q_th": y_b[2],
        "b_q_thd": om / (1.0 + y_b[0]) ** 2,
        "lo_q_r": l0 * (1.0 + y_l[0]),
        "lo_q_rd": l0 * y_l[1],
        "lo_q_th": y_l[2],
        "lo_q_thd": om / (1.0 + y_l[0]) ** 2,
    }


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
    res = geyer_stance(params, td)
    assert res.ok, res.message
    ref = _integrate_approximate_dynamics(params, td)
    got = dict(zip(STANCE_COLUMNS, (res.t_bottom, res.t_stance, *res.bottom, *res.liftoff), strict=True))
    # Measured over these cases: times <= 8.3e-14 s, lengths <= 8.9e-14 m, angles <= 4.4e-13 rad,
    # rates <= 2.7e-12 (SI units).
    for key, value in ref.items():
        assert got[key] == pytest.approx(value, rel=0, abs=1e-10), key


# ----------------------------------------------------------------------------------------------
# 4. Batch kernels == scalar kernels, bit for bit
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("params", [HUMAN_RUNNER, ROBOT_HOPPER.with_(q_r_lo=0.24)], ids=["human", "hopper"])
def test_eq7_eq20_stance_batch_bit_identical_to_scalar(params):
    rng = np.random.default_rng(7)
    n = 300
    vs, ws = math.sqrt(params.g_s * params.l0), math.sqrt(params.g_s / params.l0)
    tds = np.column_stack(
        [
            params.l0 * rng.uniform(0.85, 1.0, n),
            rng.uniform(-1.2, 0.1, n) * vs,  # some q_rd >= 0: TOUCHDOWN_NOT_COMPRESSING
            rng.uniform(-0.2, 1.4, n),  # large angles: FALL / no real solution
            rng.uniform(-4.0, 0.5, n) * ws,
        ]
    )
    out, status = geyer_stance_batch(params, tds)
    assert out.shape == (n, len(STANCE_COLUMNS)) and status.shape == (n,)
    for i in range(n):
        res = geyer_stance(params, tds[i])
        row = np.array([res.t_bottom, res.t_stance, *res.bottom, *res.liftoff])
        assert status[i] == int(res.status), i
        assert np.array_equal(out[i], row, equal_nan=True), (i, out[i], row)
    assert len(set(status.tolist())) >= 3  # OK and several failure codes are exercised


@pytest.mark.parametrize("params", [HUMAN_RUNNER, ROBOT_HOPPER], ids=["human", "hopper"])
def test_eq7_eq20_apex_return_batch_bit_identical_to_scalar(params):
    rng = np.random.default_rng(8)
    n = 300
    h = params.l0 * rng.uniform(0.8, 1.3, n)  # some below the touchdown height: APEX_TOO_LOW
    v = math.sqrt(params.g_s * params.l0) * rng.uniform(0.0, 2.5, n)
    th = rng.uniform(0.0, 0.8, n)
    out, status = apex_return_geyer_batch(params, h, v, th)
    assert out.shape == (n, len(APEX_COLUMNS))
    for i in range(n):
        res = apex_return_geyer(params, h[i], v[i], th[i])
        row = np.array([*res.next_apex, res.t_descent, res.t_stance, res.t_ascent, *res.liftoff])
        assert status[i] == int(res.status), i
        assert np.array_equal(out[i], row, equal_nan=True), (i, out[i], row)
    assert np.sum(status == Status.OK) >= 30 and len(set(status.tolist())) >= 3
    # Scalars broadcast against arrays.
    out_b, status_b = apex_return_geyer_batch(params, h[0], v, th)
    for i in range(0, n, 37):
        res = apex_return_geyer(params, h[0], v[i], th[i])
        assert status_b[i] == int(res.status)
        assert np.array_equal(out_b[i, :2], np.array(res.next_apex), equal_nan=True)


def test_approximate_vs_exact_stance_from_the_same_touchdown_direct():
    """Spot check of the grid records: the README's default case, both stances from one touchdown."""
    ex = simulate_step(HUMAN_RUNNER, 1.0, 5.0, 0.35)
    st = geyer_stance(HUMAN_RUNNER, ex.touchdown)
    direct = simulate_stance(HUMAN_RUNNER, ex.touchdown)
    assert direct.t_stance == ex.t_stance and direct.liftoff == ex.liftoff
    # README table: t_s error +1.40e-3 s, q_thd_lo error +6.73e-2 rad/s.
    assert st.t_stance - ex.t_stance == pytest.approx(1.40e-3, abs=1e-5)
    assert st.liftoff[3] - ex.liftoff[3] == pytest.approx(6.73e-2, abs=1e-4)
