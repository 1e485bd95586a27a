"""Swing-leg retraction (Seyfarth, Geyer and Herr 2003): after the apex the leg angle is
``touchdown_angle + retraction_rate * t``; the foot touches down where it meets the ground (report
section 2.1 with a swinging leg). A rate of 0 is the held leg of every earlier release."""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq
from slipmaps.runtime.api import model
from slipmaps.runtime.exact.reference import simulate_step

NAMES = [m.name for m in slipmaps.maps()]
P = slipmaps.HUMAN_RUNNER
VS = slipmaps.SlipParams(k_c=20_000.0, k_d=22_000.0)


def _params(name: str) -> slipmaps.SlipParams:
    info = next(m for m in slipmaps.maps() if m.name == name)
    return P if "constant_stiffness" in info.requires else VS


def _foot_height(t: float, h: float, th: float, ground: float, rate: float) -> float:
    """The foot's height above the touchdown ground a time t after the apex, from first principles."""
    return h - 0.5 * P.g_f * t * t - ground - P.q_r_td * math.cos(th + rate * t)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(
    h=st.floats(0.95, 1.3),
    v=st.floats(-7.0, 7.0),
    th=st.floats(-0.6, 0.6),
    ground=st.floats(-0.1, 0.1),
    rate=st.floats(-3.1, 3.1),
)
def test_sec2_1_touchdown_is_the_first_time_the_swinging_foot_meets_the_ground(h, v, th, ground, rate):
    """The descent kernel's touchdown time is the first root of the foot's height (bracketed on a
    grid and found by brentq, independently of the kernel's Newton iteration), its angle the swung
    leg's; refused (NO_TOUCHDOWN) only where the leg is past the horizontal at that root."""
    assume(_foot_height(0.0, h, th, ground, rate) > 1e-3)
    status, td = model.call(
        "apex_to_touchdown", b_y_apex=h, b_xd_apex=v, q_th_td=th, q_r_td=P.q_r_td, g_f=P.g_f, ground=ground,
        retraction_rate=rate,
    )  # fmt: skip
    # the first sign change of the foot's height on a fine grid, then brentq inside it
    grid = np.linspace(0.0, 1.0, 20001)
    heights = np.array([_foot_height(t, h, th, ground, rate) for t in grid])
    first = int(np.argmax(heights <= 0.0))
    assert first > 0
    root = brentq(_foot_height, grid[first - 1], grid[first], args=(h, th, ground, rate), xtol=1e-15)
    angle = th + rate * root
    if status == slipmaps.Status.OK:
        assert td["t_flight"] == pytest.approx(root, rel=1e-12, abs=1e-14)
        assert td["touchdown_q_th"] == pytest.approx(angle, rel=1e-12, abs=1e-14)
        assert td["foot_x"] == pytest.approx(v * root + P.q_r_td * math.sin(angle), rel=1e-12, abs=1e-13)
    else:
        assert status == slipmaps.Status.NO_TOUCHDOWN, status
        assert abs(angle) >= math.pi / 2 - 1e-9, (root, angle)


@pytest.mark.parametrize("name", NAMES)
def test_sec2_1_a_rate_of_zero_holds_the_leg(name):
    """Rate 0: the touchdown angle is the input's and the descent the closed form sqrt(2 drop/g)."""
    params = _params(name)
    r = slipmaps.apex_return(name, params, 1.0, 5.0, 0.35)
    assert r.ok, r.message
    assert r.touchdown_q_th == 0.35
    drop = 1.0 - params.q_r_td * math.cos(0.35)
    assert r.t_descent == pytest.approx(math.sqrt(2 * drop / params.g_f), rel=4 * np.finfo(float).eps)
    assert r.as_dict() == slipmaps.apex_return(name, params, 1.0, 5.0, 0.35, retraction_rate=0.0).as_dict()


@pytest.mark.parametrize("name", NAMES)
def test_every_map_touches_down_at_the_swung_angle_and_mirrors(name):
    """Every map outputs the angle it touched down with; running backward with the mirrored angle
    and rate is the mirror image (the rate is odd like the angle)."""
    params = _params(name)
    fwd = slipmaps.apex_return(name, params, 1.05, 5.0, 0.40, retraction_rate=-0.8)
    bwd = slipmaps.apex_return(name, params, 1.05, -5.0, -0.40, retraction_rate=0.8)
    assert fwd.ok and bwd.ok, (fwd.message, bwd.message)
    assert fwd.touchdown_q_th == pytest.approx(0.40 - 0.8 * fwd.t_descent, rel=1e-15)
    assert fwd.touchdown_q_th < 0.40
    assert bwd.touchdown_q_th == -fwd.touchdown_q_th
    assert bwd.next_apex_height == fwd.next_apex_height and bwd.next_apex_speed == -fwd.next_apex_speed


@pytest.mark.parametrize("rate", [-1.5, -0.5, 0.5])
def test_the_exact_map_with_retraction_is_the_solve_ivp_reference(rate):
    """The generated exact map against the solve_ivp reference, both descending with the swinging leg."""
    exact = slipmaps.apex_return("exact", VS, 1.05, 5.0, 0.5, retraction_rate=rate)
    ref = simulate_step(VS, 1.05, 5.0, 0.5, retraction_rate=rate, rtol=1e-12, atol=1e-12)
    assert exact.ok and ref.status == slipmaps.Status.OK, (exact.message, ref.message)
    assert exact.next_apex_height == pytest.approx(ref.next_apex[0], rel=1e-9)
    assert exact.next_apex_speed == pytest.approx(ref.next_apex[1], rel=1e-9)


def test_rates_beyond_the_concave_range_or_past_the_horizontal_are_refused():
    """Beyond |rate| = sqrt(g_f/q_r_td) the foot's height may touch the ground more than once:
    INVALID_INPUT; a leg swung past the horizontal before touchdown: NO_TOUCHDOWN. No NaN reaches
    the stance."""
    bound = math.sqrt(P.g_f / P.q_r_td)
    r = slipmaps.apex_return("geyer", P, 1.0, 5.0, 0.35, retraction_rate=-1.001 * bound)
    assert r.status == slipmaps.Status.INVALID_INPUT, r.message
    assert math.isnan(r.next_apex_height)
    assert slipmaps.apex_return("geyer", P, 1.0, 5.0, 0.35, retraction_rate=-0.999 * bound).status != (
        slipmaps.Status.INVALID_INPUT
    )
    r = slipmaps.apex_return("geyer", P, 1.3, 5.0, 1.2, retraction_rate=3.0)
    assert r.status == slipmaps.Status.NO_TOUCHDOWN, r.message


@pytest.mark.parametrize(
    "params",
    [P, slipmaps.ROBOT_HOPPER, P.with_(q_r_td=0.9, g_f=9.0)],
    ids=["human", "hopper", "short-touchdown"],
)
def test_the_rates_declared_range_is_the_kernels_and_the_calls_say_it(params):
    """derive/params.py's row declares |rate| <= sqrt(g_f/q_r_td) once: the flight kernels guard it
    (INVALID_INPUT just beyond, not just within), the Python layer reads the same bound
    (validate.limit), a scalar call's INVALID_INPUT message names the input and its range, and a
    deadbeat plan refuses it in one line (it said only "an input is not finite or outside its
    valid range")."""
    from slipmaps.runtime.api.validate import limit

    bound = limit("retraction_rate", params)
    assert bound == pytest.approx(math.sqrt(params.g_f / params.q_r_td), rel=1e-15)
    name = "geyer" if params.constant_stiffness else "geyer-vs"
    h, th = 1.0 * params.l0, 0.35
    within = slipmaps.apex_return(name, params, h, 0.0, th, retraction_rate=-0.999 * bound)
    assert within.status != slipmaps.Status.INVALID_INPUT, within.message
    text = f"[{-bound:.6g}, {bound:.6g}] rad/s (|retraction_rate| <= sqrt(g_f/q_r_td)"
    for call in (slipmaps.apex_return, slipmaps.apex_return_jacobian):
        r = call(name, params, h, 0.0, th, retraction_rate=-1.001 * bound)
        assert r.status == slipmaps.Status.INVALID_INPUT
        assert r.message.startswith(f"retraction_rate={-1.001 * bound!r} is outside its range {text}"), (
            r.message
        )
    with pytest.raises(ValueError, match=r"^retraction_rate must lie in \[") as err:
        slipmaps.deadbeat("iterative", params, h, 1.0, h, 1.0, retraction_rate=2 * bound)
    assert text in str(err.value) and "\n" not in str(err.value)
