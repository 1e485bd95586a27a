"""Swing-leg policies (runtime/control/swing.py): the controls as functions of the time since the apex,
from a batch deadbeat over grounds (Wu and Geyer 2013's time-based control), and the runs and plant
that fly them (report section 2.1's touchdown with a leg whose angle changes in flight)."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import slipmaps
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq
from slipmaps.runtime.control import swing_tables
from slipmaps.runtime.control.plant import Plant
from slipmaps.runtime.control.runs import PLAN_NAMES
from slipmaps.runtime.control.scenarios import from_dict, load
from slipmaps.runtime.exact.reference import simulate_step

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
P = slipmaps.HUMAN_RUNNER
H, V, D = 1.3, 5.0, 0.3  # the blind-running example's apex, target and ground range
CONTROLS = ("touchdown_angle", "k_d")


@pytest.fixture(scope="module")
def policy():
    return slipmaps.swing_policy("iterative", P, H, V, H, V, grounds=(-D, D), controls=CONTROLS)


def _foot(t, h, g, policy):
    """The foot's height above ground ``g`` a time t after the apex, the angle the policy's."""
    th = float(policy.controls_at(np.array([t]))["touchdown_angle"][0])
    return h - 0.5 * P.g_f * t * t - g - P.q_r_td * math.cos(th)


def test_the_policy_reaches_the_target_on_every_ground_of_its_table(policy):
    assert policy.reached.all() and policy.used.all()
    assert np.all(np.diff(policy.t_touchdown) > 0)  # the highest ground meets the leg first
    assert (
        np.max(np.abs(policy.next_apex_height - H)) < 1e-8
        and np.max(np.abs(policy.next_apex_speed - V)) < 1e-8
    )


def test_a_policys_former_names_of_the_next_apex_read_with_a_warning(policy):
    assert {"next_apex_height", "next_apex_speed"} <= set(policy.to_pandas().columns)
    with pytest.warns(DeprecationWarning, match="'next_height' of a swing policy to 'next_apex_height'"):
        assert np.array_equal(policy.next_height, policy.next_apex_height)


def test_sec2_1_the_policys_leg_meets_every_ground_at_the_first_root_of_the_foots_height(policy):
    """The touchdown of the interpolated policy (bisection in swing_tables) against brentq on the
    first sign change of the foot's height on a fine grid."""
    grounds = np.linspace(-D, D, 23)
    td = policy.touchdown(grounds)
    checked = 0
    for g, t in zip(grounds, td["t"], strict=True):
        grid = np.linspace(0.0, 0.6, 3001)
        heights = np.array([_foot(x, H, g, policy) for x in grid])
        first = int(np.argmax(heights <= 0.0))
        root = brentq(_foot, grid[first - 1], grid[first], args=(H, g, policy), xtol=1e-15)
        assert t == pytest.approx(root, abs=1e-12)
        checked += 1
    assert checked == grounds.size
    assert set(td["status"].tolist()) == {0}  # REACHED: inside the table, both knots reached


def test_the_policys_step_on_the_exact_plant_reaches_the_target_across_its_range(policy):
    """Grounds between the knots, the exact plant: the next apex within the model's own error and the
    interpolation's (measured: 7e-6 m and 9e-6 m/s with iterative as the model; bound 5x)."""
    grounds = np.random.default_rng(3).uniform(-D, D, 40)
    td = policy.touchdown(grounds)
    steps = Plant("exact", P).step(H, V, td["touchdown_angle"], grounds, td["k_c"], td["k_d"])
    assert steps.ok.all()
    assert np.max(np.abs(steps.next_apex_height - H)) < 5e-5
    assert np.max(np.abs(steps.next_apex_speed - V)) < 5e-5
    assert np.allclose(steps.t_descent, td["t"], rtol=0, atol=1e-12)  # the plant's touchdown is the policy's


def test_the_time_varying_leg_against_the_exact_simulator(policy):
    """An independent step (scipy's solve_ivp, runtime/exact/reference.py) from the touchdown the policy
    gives: the leg is massless, so the stance depends on the touchdown state alone."""
    plant = Plant("exact", P)
    for g in (-0.27, -0.05, 0.11, 0.29):
        td = policy.touchdown(np.array([g]))
        th, kd = float(td["touchdown_angle"][0]), float(td["k_d"][0])
        ref = simulate_step(P.with_(k_d=kd), H, V, th, ground=g)
        got = plant.step(H, V, th, g, P.k_c, kd)
        assert ref.t_descent == pytest.approx(float(td["t"][0]), abs=1e-12)
        assert got.next_apex_height[0] == pytest.approx(ref.next_apex[0], abs=1e-7)
        assert got.next_apex_speed[0] == pytest.approx(ref.next_apex[1], abs=1e-7)


def test_the_interpolation_error_falls_as_the_cube_of_the_knot_spacing():
    """The representation error (the model's next apex at the interpolated controls against the
    target, between the knots): three-point Hermite slopes, third order; measured ratio about 8 per
    halving of the spacing."""
    errors = []
    for n in (16, 32):
        pol = slipmaps.swing_policy("geyer", P, H, V, None, V, grounds=(-D, D), n=n)
        err = pol.representation_error()
        assert err["samples"] > 0
        errors.append(err["speed"])
    assert errors[1] < errors[0] / 5.0
    assert errors[1] < 1e-4


def test_a_ground_outside_the_range_holds_the_end_controls(policy):
    td = policy.touchdown(np.array([D + 0.05, -D - 0.05]))
    assert td["status"].tolist() == [3, 3]  # OUT_OF_RANGE
    assert PLAN_NAMES[3] == "OUT_OF_RANGE"
    assert td["touchdown_angle"][0] == policy.touchdown_angle[0]
    assert td["touchdown_angle"][1] == policy.touchdown_angle[-1]


def test_an_unreachable_ground_holds_the_closest_apex_and_says_so():
    """From a 1.3 m apex a ground 0.5 m up leaves too little energy budget for the target: the table
    holds the closest reachable next apex, status UNREACHABLE per ground."""
    pol = slipmaps.swing_policy("iterative", P, H, V, H, V, grounds=(-0.5, 0.5), controls=CONTROLS, n=16)
    status = pol.status
    assert "UNREACHABLE" in set(status) and "REACHED" in set(status)
    bad = status == "UNREACHABLE"
    assert np.all(pol.grounds[bad] > pol.grounds[~bad].max())  # the highest grounds
    assert np.all(np.isfinite(pol.next_apex_height[bad]))
    frame = pol.to_pandas()
    assert list(frame["status"]) == list(status) and len(frame) == 16
    assert json.loads(json.dumps(pol.as_dict()))["status"] == list(status)


@settings(max_examples=60, deadline=None)
@given(
    h=st.floats(1.0, 1.6),
    slope=st.floats(-0.4, 0.4),
    curve=st.floats(-0.5, 0.5),
    ground=st.floats(-0.5, 0.5),
    n=st.integers(2, 12),
)
def test_the_touchdown_of_any_table_is_the_first_root(h, slope, curve, ground, n):
    """For a table of knots in increasing time and any ground: the foot is above the ground at every
    sampled time before the touchdown the kernel returns, and at it on the ground (or it is below at
    the apex already: NaN)."""
    T = np.linspace(0.1, 0.45, n)[None, :]
    A = (0.35 + slope * T + curve * (T - 0.25) ** 2).copy()
    M = np.full_like(T, np.nan)
    counts = np.array([n])
    swing_tables.slopes_rows(T, A, counts, M)
    t, a = np.empty(1), np.empty(1)
    where, knot = np.empty(1, dtype=np.int64), np.empty(1, dtype=np.int64)
    swing_tables.touchdown_rows(
        np.array([h]), np.array([ground]), P.g_f, P.q_r_td, T, A, M, counts, t, a, where, knot
    )

    def foot(x):
        y = np.empty(1)
        swing_tables.evaluate_rows(T, A, M, counts, np.array([x]), y)
        return h - 0.5 * P.g_f * x * x - ground - P.q_r_td * math.cos(y[0])

    if math.isnan(t[0]):
        assert foot(0.0) < 0.0
        return
    assert abs(foot(t[0])) < 1e-9
    assert all(foot(x) > -1e-12 for x in np.linspace(0.0, t[0], 200)[:-1])


def test_the_blind_running_example_runs_and_reaches_its_targets():
    r = slipmaps.run(EXAMPLES / "blind_running.toml", steps=6)
    assert not r.fell and len(r) == 6
    reached = np.array([s["plan_status"] for s in r.steps])
    dh, dv = r.errors()
    ok = reached == "REACHED"
    assert ok.sum() >= 4  # the filter is not empty
    assert np.max(np.abs(dh[ok])) < 1e-3 and np.max(np.abs(dv[ok])) < 5e-3
    swing = r.batch.swing[0, :6]
    assert np.all(np.isfinite(swing))
    # the swing leg's record ends at the angle it touched down with
    assert np.allclose(swing[:, -1], r.column("touchdown_angle"), atol=1e-12)


def test_a_retracting_run_touches_down_at_the_swung_angle():
    r = slipmaps.run(
        {"steps": 3, "start": {"height": 1.1}, "control": {"policy": "retraction", "retraction_rate": -1.0}}
    )
    assert not r.fell
    swing_angle, td_angle, t_d = r.column("swing_angle"), r.column("touchdown_angle"), r.column("t_descent")
    assert np.allclose(td_angle, swing_angle - 1.0 * t_d, atol=1e-12)
    assert np.all(td_angle < swing_angle)


@pytest.mark.parametrize(
    ("control", "message"),
    [
        ({"policy": "sideways"}, r"\[control\] policy: must be one of apex, retraction, time-based"),
        ({"retraction_rate": -1.0}, r"\[control\] retraction_rate: is the rate of policy 'retraction'"),
        ({"policy": "time-based", "fixed_angle": 0.4}, "cannot go with fixed_angle"),
        ({"policy": "time-based", "grounds": [0.2, -0.2]}, "low < high"),
        ({"policy": "time-based", "knots": 1}, "knots"),
    ],
)
def test_swing_settings_that_do_not_go_together_are_refused_naming_the_key(control, message):
    with pytest.raises(ValueError, match=message):
        from_dict({"control": control}, where="s.toml")


def test_the_swing_policy_refuses_a_bad_range():
    with pytest.raises(ValueError, match="low < high"):
        slipmaps.swing_policy("geyer", P, H, V, None, V, grounds=(0.2, -0.2))
    with pytest.raises(ValueError, match="n must be an integer >= 2"):
        slipmaps.swing_policy("geyer", P, H, V, None, V, n=1)


def test_the_command_line_flies_a_policy(tmp_path):
    cmd = [sys.executable, "-m", "slipmaps", "run", str(EXAMPLES / "rough_ground.toml"), "--steps", "3"]
    cmd += ["--known", "0", "--policy", "time-based", "--figure", str(tmp_path / "run.png"), "--json"]
    out = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["scenario"]["policy"] == "time-based" and len(data["steps"]) == 3
    assert (tmp_path / "run.png").stat().st_size > 10_000
    bad = subprocess.run(
        [*cmd[:5], "--retraction-rate", "-1", "--policy", "apex", "--no-figure"],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert bad.returncode == 2 and "retraction_rate" in bad.stderr and "Traceback" not in bad.stderr


def test_the_example_loads_with_its_policy():
    sc = load(EXAMPLES / "blind_running.toml")
    assert (sc.policy, sc.controls, sc.grounds, sc.knots, sc.known) == (
        "time-based",
        CONTROLS,
        (-D, D),
        64,
        0,
    )
