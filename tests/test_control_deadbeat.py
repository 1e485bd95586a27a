"""The deadbeat controller (runtime/control/deadbeat.py, compiled.py, bottom.py): the controls it
returns take the map's step to the target (checked with slipmaps.apex_return itself), its statuses
say what happened, bounds hold, the batch is the scalar solve, the mirror image is the mirror image,
the least-change preference and the energy budget are what they say.

Tolerances are measured (the value in each comment); the solver's tol is 1e-9 on the scaled
residual (height / l0, speed / sqrt(g l0)).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
from slipmaps import PlanStatus
from slipmaps.runtime.cli.flight import next_apex, touchdown
from slipmaps.runtime.control.deadbeat import Deadbeat

P = slipmaps.HUMAN_RUNNER
SCALE_V = math.sqrt(P.g_f * P.l0)


def _check(name, res, h, v, ground=0.0):
    """The map's own step at the returned controls."""
    params = P.with_(k=res.k_c) if res.k_c == res.k_d else P.with_(k_c=res.k_c, k_d=res.k_d)
    return slipmaps.apex_return(name, params, h, v, res.touchdown_angle, ground=ground)


@pytest.mark.parametrize("name", ["iterative", "exact", "geyer-vs"])
def test_the_angle_and_k_d_reach_the_target_on_the_map_itself(name):
    res = slipmaps.deadbeat(name, P, 1.0, 5.0, 1.02, 5.2)
    assert res.status == PlanStatus.REACHED and res.reached and res.ok, res.message
    step = _check(name, res, 1.0, 5.0)
    assert step.ok
    # measured: 7e-12 (iterative), 4e-12 (exact) of the scaled residual
    assert abs(step.next_apex_height - 1.02) < 1e-9 * P.l0
    assert abs(step.next_apex_speed - 5.2) < 1e-9 * SCALE_V
    assert step.next_apex_height == res.next_apex_height and step.next_apex_speed == res.next_apex_speed
    assert res.residual < 1e-9
    assert P.k_c * 0.5 <= res.k_d <= P.k_c * 2.0 and res.k_c == P.k_c


def test_the_angle_alone_targets_the_speed_and_reports_the_height():
    res = slipmaps.deadbeat("exact", P, 1.0, 5.0, 1.0, 5.2, controls=("touchdown_angle",))
    assert res.reached, res.message
    assert res.k_c == res.k_d == P.k_c
    step = _check("exact", res, 1.0, 5.0)
    assert abs(step.next_apex_speed - 5.2) < 1e-9 * SCALE_V
    # the energy fixes the height: (5^2 - 5.2^2) / (2 g) below 1 m (measured 0.8960 m)
    assert res.next_apex_height == pytest.approx(1.0 + (25.0 - 5.2**2) / (2 * P.g_f), abs=1e-8)
    assert math.isnan(res.target_height) and res.target_speed == 5.2


def test_the_angle_alone_targets_the_height_when_no_speed_is_given():
    res = slipmaps.deadbeat("geyer", P, 1.0, 5.0, 1.0, None, controls=("touchdown_angle",))
    assert res.reached, res.message
    step = _check("geyer", res, 1.0, 5.0)
    assert abs(step.next_apex_height - 1.0) < 1e-9
    assert math.isnan(res.target_speed)


def test_a_target_beyond_the_energy_budget_is_unreachable_with_the_closest_apex_and_why():
    res = slipmaps.deadbeat("exact", P, 1.0, 5.0, 1.0, 5.5)  # +210 J, k_d <= 2 k_c gives +123 J (measured)
    assert res.status == PlanStatus.UNREACHABLE and res.ok and not res.reached
    assert "k_d" in res.at_bounds and res.k_d == 2.0 * P.k_c
    lo, hi = res.energy_range
    assert res.energy_needed == pytest.approx(210.0, abs=1e-9)
    assert hi == pytest.approx(res.energy_change, abs=1e-9) and hi < res.energy_needed  # measured +122.9 J
    assert "unreachable" in res.message and "k_d at its upper bound 40000" in res.message
    assert (
        f"needs +210 J and k_d at its upper bound makes this step's energy change {hi:+.4g} J" in res.message
    )
    step = _check("exact", res, 1.0, 5.0)
    assert step.next_apex_height == res.next_apex_height and step.next_apex_speed == res.next_apex_speed

    # the closest: no nearby angle (k_d at its bound) comes closer in the scaled norm
    def dist(th):
        s = slipmaps.apex_return("exact", P.with_(k_d=res.k_d), 1.0, 5.0, th)
        return math.hypot((s.next_apex_height - 1.0) / P.l0, (s.next_apex_speed - 5.5) / SCALE_V)

    assert res.residual == pytest.approx(dist(res.touchdown_angle), rel=1e-12)
    for dth in (-1e-3, 1e-3):
        assert dist(res.touchdown_angle + dth) > res.residual


def test_the_energy_budget_is_what_k_d_at_its_bounds_makes_of_the_step():
    """For the exact map dE'/dk_d is (l0 - q_r_b)^2 / 2 at every k_d (the bottom does not depend on
    k_d), so the budget is exact: measured to 3e-9 J."""
    res = slipmaps.deadbeat("exact", P, 1.0, 5.0, 1.0, 5.1)
    assert res.reached
    e_in = P.m * (P.g_f * 1.0 + 12.5)
    for k_d, bound in zip((0.5 * P.k_c, 2.0 * P.k_c), res.energy_range, strict=True):
        s = slipmaps.apex_return("exact", P.with_(k_d=k_d), 1.0, 5.0, res.touchdown_angle)
        assert P.m * (P.g_f * s.next_apex_height + 0.5 * s.next_apex_speed**2) - e_in == pytest.approx(
            bound, abs=1e-6
        )


def test_the_map_failing_at_every_control_is_map_failed():
    res = slipmaps.deadbeat("iterative", P, 0.3, 2.0, 1.0, 2.0)  # below the leg at any angle
    assert res.status == PlanStatus.MAP_FAILED and not res.ok
    assert res.map_status == slipmaps.Status.APEX_TOO_LOW
    assert "APEX_TOO_LOW" in res.message
    assert math.isnan(res.next_apex_height) and math.isnan(res.residual)


def test_bounds_hold_and_bad_bounds_are_refused():
    bounds = {"k_d": (18_000.0, 22_000.0), "touchdown_angle": (0.2, 0.45)}
    res = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.5, bounds=bounds)
    assert res.status == PlanStatus.UNREACHABLE
    assert 18_000.0 <= res.k_d <= 22_000.0 and 0.2 <= res.touchdown_angle <= 0.45
    for bad, needle in (
        ({"k_d": (2.0, 1.0)}, "low < high"),
        ({"k_d": (-1.0, 1.0)}, "positive"),
        ({"kd": (1.0, 2.0)}, "unknown control 'kd'"),
        ({"touchdown_angle": (0.0, 2.0)}, "pi/2"),
    ):
        with pytest.raises(ValueError, match=needle):
            slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.0, bounds=bad)


def test_controls_a_map_does_not_have_are_refused_naming_the_maps_that_do():
    with pytest.raises(ValueError, match="constant stiffness.*iterative"):
        slipmaps.deadbeat("geyer", P, 1.0, 5.0, 1.0, 5.0, controls=("touchdown_angle", "k_d"))
    with pytest.raises(ValueError, match="constant-stiffness maps"):
        slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.0, controls=("touchdown_angle", "k"))
    with pytest.raises(ValueError, match="unknown control"):
        slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.0, controls=("angle",))
    with pytest.raises(ValueError, match="target"):
        slipmaps.deadbeat("iterative", P, 1.0, 5.0, None, None)
    with pytest.raises(TypeError):
        slipmaps.deadbeat("iterative", P, "1.0", 5.0, 1.0, 5.0)
    with pytest.raises(ValueError, match="compiled kernels"):
        slipmaps.deadbeat("exact", P, 1.0, 5.0, 1.0, 5.0, method="scipy")


def test_a_constant_stiffness_map_controls_k_for_both_halves():
    res = slipmaps.deadbeat("geyer", P, 1.0, 5.0, 1.0, 5.05, controls=("touchdown_angle", "k"))
    assert res.ok and res.k_c == res.k_d
    step = _check("geyer", res, 1.0, 5.0)
    assert step.next_apex_height == res.next_apex_height


def test_the_batch_is_the_scalar_solve_row_by_row():
    h = np.array([1.0, 1.05, 0.98, math.nan, 1.0, 0.3])
    v = np.array([5.0, 4.0, 6.0, 5.0, -5.0, 2.0])
    H, V = 1.0, np.array([5.2, 4.2, 5.8, 5.0, -5.2, 2.0])
    batch = slipmaps.deadbeat_batch("iterative", P, h, v, H, V)
    assert batch.shape == (6,)
    assert batch.counts() == {"REACHED": 4, "MAP_FAILED": 2}
    assert batch["map_status"][3] == slipmaps.Status.INVALID_INPUT
    for i in (0, 1, 2, 4, 5):
        one = slipmaps.deadbeat("iterative", P, h[i], v[i], H, V[i])
        assert one.status.value == ("REACHED", "UNREACHABLE", "MAP_FAILED")[batch["status"][i]]
        if one.ok:
            assert one.touchdown_angle == batch["touchdown_angle"][i] and one.k_d == batch["k_d"][i]
            assert one.next_apex_speed == batch["next_apex_speed"][i]


def test_running_backward_is_the_mirror_image_and_a_hop_in_place_stays_in_place():
    fwd = slipmaps.deadbeat("exact", P, 1.0, 4.0, 1.02, 4.2)
    back = slipmaps.deadbeat("exact", P, 1.0, -4.0, 1.02, -4.2)
    assert fwd.reached and back.reached
    assert back.touchdown_angle == pytest.approx(-fwd.touchdown_angle, abs=1e-12)  # measured: 0
    assert back.k_d == pytest.approx(fwd.k_d, rel=1e-12)
    hop = slipmaps.deadbeat("exact", P, 1.2, 0.0, 1.2, 0.0)
    assert hop.reached and hop.touchdown_angle == 0.0 and hop.next_apex_speed == 0.0
    # from a hop in place the toe on the +x side pushes the body toward -x
    turn = slipmaps.deadbeat("exact", P, 1.2, 0.0, 1.2, -1.0)
    assert turn.reached and turn.touchdown_angle > 0.0


def test_with_a_control_to_spare_the_stiffness_changes_least():
    """(angle, k_c, k_d) reaches the target with a smaller stiffness change from the nominal than
    (angle, k_d), a solution it could have returned (measured 0.30 against 0.46 of k_c)."""
    two = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.2)
    three = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.2, controls=("touchdown_angle", "k_c", "k_d"))
    assert two.reached and three.reached
    change = lambda r: math.hypot(r.k_c - P.k_c, r.k_d - P.k_d) / P.k_c  # noqa: E731
    assert change(three) < change(two)
    assert three.k_c < P.k_c < three.k_d  # a softer compression stores more energy to release
    step = _check("iterative", three, 1.0, 5.0)
    assert abs(step.next_apex_speed - 5.2) < 1e-9 * SCALE_V


def test_broyden_and_newton_reach_the_same_controls():
    b = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.03, 4.9)
    n = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.03, 4.9, jacobian="newton")
    assert b.reached and n.reached
    assert b.touchdown_angle == pytest.approx(n.touchdown_angle, abs=1e-9)  # measured 3e-12
    assert b.k_d == pytest.approx(n.k_d, rel=1e-8)
    assert n.jacobians > b.jacobians == 1


def test_one_control_is_bracketed_when_newton_starts_far():
    """From a start on the wrong side of the gait the scan and the bracket find the root; the
    result equals scipy's brentq on the map to 1e-9 rad."""
    from scipy.optimize import brentq

    res = slipmaps.deadbeat(
        "geyer", P, 1.0, 5.0, 1.0, None, controls=("touchdown_angle",), touchdown_angle=-1.0
    )
    assert res.reached
    root = brentq(
        lambda th: slipmaps.apex_return("geyer", P, 1.0, 5.0, th).next_apex_height - 1.0, 0.36, 0.46
    )
    assert res.touchdown_angle == pytest.approx(root, abs=1e-9)


def test_the_bottom_stage_removes_the_compression_halfs_error():
    """k_d chosen at the exact bottom state: exact-decompression lands on the target height to the
    solver's tol, iterative-decompression within 1e-6 m of it on the exact plant (measured 9.6e-7 m)."""
    st, td, _ = touchdown(P, 1.0, 5.0, 0.36)
    bottom = slipmaps.half_stance("exact-compression", P, td).end
    for half, tol in (("exact-decompression", 1e-9), ("iterative-decompression", 2e-6)):
        b = slipmaps.BottomDeadbeat(half, P, aim="height").plan(bottom, 1.0, 5.2)
        assert b.status == PlanStatus.REACHED
        up = slipmaps.half_stance("exact-decompression", P.with_(k_d=b.k_d), bottom)
        status, h, v = next_apex(P, up.end, 1.0)
        assert status == slipmaps.Status.OK
        assert abs(h - 1.0) < tol
    both = slipmaps.BottomDeadbeat("exact-decompression", P).plan(bottom, 1.0, 5.2)
    assert both.status == PlanStatus.UNREACHABLE  # one control, two targets: least squares
    assert both.residual > 0.0
    with pytest.raises(ValueError, match="decompression half"):
        slipmaps.BottomDeadbeat("exact-compression", P)


def test_the_pages_bottom_stage_example_reaches_what_its_comment_says():
    """docs/control_planning.md's BottomDeadbeat line asked for 1.0 m and 4.9 m/s from its bottom
    and got UNREACHABLE at the k_d bound without a word; it now aims at the height (one control,
    one target) and reaches, and the both-target call from that bottom is the UNREACHABLE it says."""
    from documents import section_block

    block = section_block("docs/control_planning.md", "Control: deadbeat steps, runs on the exact plant")
    (line,) = [x for x in block.splitlines() if x.startswith("up = slipmaps.BottomDeadbeat(")]
    params = slipmaps.SlipParams(m=80.0, l0=1.0, k=20_000.0)  # docs/getting_started.md's
    down = slipmaps.half_stance("iterative-compression", params, (1.0, -1.5, 0.35, -4.5))
    scope = {"slipmaps": slipmaps, "params": params, "down": down}
    exec(line, scope)
    up = scope["up"]
    assert up.status == PlanStatus.REACHED and abs(up.next_apex_height - 0.97) < 1e-9  # measured 7e-10
    assert "# REACHED, 30061 N/m" in block and round(up.k_d) == 30061
    both = slipmaps.BottomDeadbeat("iterative-decompression", params).plan(down.end, 1.0, 4.9)
    assert both.status == PlanStatus.UNREACHABLE and both.k_d == 40_000.0  # at the bound 2 k_c


def test_a_warm_started_solve_takes_few_generated_jacobians():
    """The generated Jacobian once, then Broyden's updates (a fresh one when a line search fails):
    measured 2 Jacobians and 10 apex evaluations from 1e-3 rad away (1 and 8-12 from 1e-2 to
    5e-2 rad)."""
    ctl = Deadbeat("iterative", P)
    first = ctl.plan(1.0, 5.0, 1.0, 5.1)
    again = ctl.plan(1.0, 5.0, 1.0, 5.1, touchdown_angle=first.touchdown_angle + 1e-3)
    assert again.reached and 1 <= again.jacobians <= 2
    assert again.evaluations <= 12  # measured 10, two of them the energy budget at the k_d bounds


#: (apex height, speed, target height, speed, ground, retraction rate) of plans on the iterative map
#: applied on the exact plant.
PLANS = [
    (1.0, 5.0, 1.02, 5.2, 0.0, 0.0),
    (1.05, 4.0, 1.0, 4.2, 0.05, 0.0),
    (1.0, 5.0, 1.0, 5.0, 0.0, -2.0),
    (1.1, 3.0, 1.1, 3.3, 0.0, 0.0),
]


@pytest.mark.parametrize(("h", "v", "H", "V", "ground", "rate"), PLANS)
def test_a_plan_applied_on_the_exact_plant_lands_within_the_models_accuracy(h, v, H, V, ground, rate):
    """``plan.apply()``: the exact map steps from the plan's apex, over its ground, with its angle
    (retracting at its rate) and its k_c, k_d. A plan the iterative map REACHED lands on the exact
    plant within the iterative map's accuracy: measured at most 6.0e-6 m and 1.9e-5 m/s over 8
    plans (these 4 and (1, 5) -> (1, 4.8), (1, 5.1) on ground -0.05, (1, -5) -> (1, -5.2));
    bounded at 1e-5 m and 3e-5 m/s."""
    plan = slipmaps.deadbeat("iterative", P, h, v, H, V, ground=ground, retraction_rate=rate)
    assert plan.reached, plan.message
    exact = plan.apply()
    assert exact.ok and exact.map == "exact"
    assert abs(exact.next_apex_height - H) < 1e-5 and abs(exact.next_apex_speed - V) < 3e-5
    assert exact.inputs["touchdown_angle"] == plan.touchdown_angle and exact.inputs["ground"] == ground
    # the map the plan was made on lands where it predicted (bitwise)
    model = slipmaps.apply_plan(plan, "iterative")
    assert (model.next_apex_height, model.next_apex_speed) == (plan.next_apex_height, plan.next_apex_speed)


def test_apply_is_the_step_with_the_plans_stiffness_and_refuses_a_plan_without_controls():
    plan = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.2)
    heavy = P.with_(m=1.1 * P.m)  # a plant heavier than the model: its parameters, the plan's stiffness
    got = plan.apply(params=heavy)
    by_hand = slipmaps.apex_return("exact", heavy.with_(k_d=plan.k_d), 1.0, 5.0, plan.touchdown_angle)
    assert got.values == by_hand.values and got.next_apex_speed != plan.apply().next_apex_speed
    with pytest.raises(ValueError, match="needs a constant leg stiffness"):
        plan.apply("geyer")  # k_c != k_d: a map with one stiffness cannot take it
    failed = slipmaps.deadbeat("iterative", P, 0.3, 2.0, 1.0, 2.0)
    assert failed.status == PlanStatus.MAP_FAILED
    with pytest.raises(ValueError, match="status MAP_FAILED.*no controls to apply"):
        failed.apply()
