"""Footholds over stepping stones (runtime/control/stones.py, footholds.py, footholds_solver.py,
footholds_runs.py): courses and their one-line errors, the planner's choice of stones, a miss as the
runs record it, horizon 2 against horizon 1, the deadbeat baseline, the robot's terrain."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.control.footholds import Footholds, FootholdStatus
from slipmaps.runtime.control.scenarios import from_dict, load
from slipmaps.runtime.control.stones import MISSED, Course, CourseError, met, random_course

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "stones.toml"
P = slipmaps.HUMAN_RUNNER
#: A course with three candidate sequences for two hops from a 1 m apex at 5 m/s, one of them
#: feasible (stones 1 then 3: stone 2 is too near for a second hop after 1 and too far back for the
#: nominal step after it to reach 3 or 4; measured, planned margins 0.125 m and 0.115 m).
ONE_WAY = [
    [0.0, 0.3, 0.0],
    [0.94, 1.23, 0.0],
    [1.62, 1.84, 0.0],
    [3.14, 3.41, 0.0],
    [4.0, 4.15, 0.0],
    [5.65, 10.15, 0.0],
]


# ----------------------------------------------------------------------------------------------
# courses
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("stones", "margin", "words"),
    [
        ([[0.0, 1.0, 0.0], [0.8, 1.5, 0.0]], 0.0, "stone 1 ([0.8, 1.5] m) overlaps stone 0"),
        ([[0.0, 1.0, 0.0], [1.5, 1.8, 0.0]], 0.2, "stone 1 ([1.5, 1.8] m, 0.3 m wide) has no usable part"),
        ([[0.0, 1.0, 0.0], [2.0, 1.8, 0.0]], 0.0, "stone 1 must have x_b > x_a"),
        ([[0.0, 1.0, math.nan]], 0.0, "stones[0] must hold finite numbers"),
        ([[0.0, 1.0]], 0.0, "stones[0] must be [x_a, x_b, height]"),
        ([], 0.0, "at least one stone"),
    ],
)
def test_a_bad_course_is_one_line_naming_the_stone(stones, margin, words):
    with pytest.raises(CourseError, match=None) as err:
        Course.of(stones, margin)
    text = str(err.value)
    assert words in text and "\n" not in text


def test_a_drawn_course_keeps_its_ranges_and_its_seed():
    c = random_course(3, count=50, width=(0.3, 0.6), gap=(0.2, 0.8), rise=0.1, margin=0.02)
    widths = np.asarray(c.x_b) - np.asarray(c.x_a)
    rises = np.diff(c.heights)
    assert len(c) == 50 and c.x_a[0] == 0.0 and c.height[0] == 0.0
    # edges rounded to the millimetre: the ranges within 1 mm
    assert widths.min() >= 0.3 - 1e-3 and widths.max() <= 0.6 + 1e-3
    assert c.gaps().min() >= 0.2 - 1e-3 and c.gaps().max() <= 0.8 + 1e-3
    assert np.abs(rises).max() <= 0.1 + 1e-3 and np.abs(rises).max() > 0.05
    assert c == random_course(3, count=50, width=(0.3, 0.6), gap=(0.2, 0.8), rise=0.1, margin=0.02)


def test_a_foot_lands_on_a_stones_usable_part_or_misses():
    c = Course.of([[0.0, 1.0, 0.0], [1.5, 2.0, 0.1]], 0.05)
    got = c.landing([0.5, 0.97, 1.2, 1.56, 2.1, math.nan])
    assert got.tolist() == [0, -1, -1, 1, -1, -1]
    assert c.ahead(0.96, 5).tolist() == [1]  # stone 0's usable part ends at 0.95


def test_a_falling_foot_meets_the_highest_stone_under_it():
    c = Course.of([[0.0, 1.0, 0.2], [1.0, 2.0, 0.0], [2.5, 3.0, 0.3]])
    cand = np.array([[0, 1, 2], [0, 1, 2], [0, 1, 2]])
    # the foot's x when it is at each stone's height: over stone 0 at its height (met, the highest),
    # past stone 0 and over stone 1 at its height, past every stone (a miss)
    foot = np.array([[0.5, 0.7, 0.4], [1.2, 1.4, math.nan], [2.1, 2.2, 2.05]])
    assert met(c, cand, foot).tolist() == [0, 1, -1]


def test_a_stones_scenario_lists_or_draws_its_course():
    sc = load(EXAMPLE)
    assert len(sc.stones) == 32 and sc.stones.margin == 0.02 and sc.horizon == 2 and sc.lookahead == 10
    drawn = {"count": 32, "width": [0.3, 0.6], "gap": [0.2, 0.8], "rise": 0.05, "seed": 4, "margin": 0.02}
    sc2 = from_dict({"terrain": {"kind": "stones", **drawn}, "control": {"policy": "footholds"}})
    assert sc2.stones == sc.stones  # the example lists random_course(4, ...) by hand, rounded
    with pytest.raises(ValueError, match=r"\[terrain\] seed: is a key of a drawn course"):
        from_dict({"terrain": {"kind": "stones", "stones": [[0.0, 1.0, 0.0]], "seed": 1}})
    with pytest.raises(ValueError, match=r"\[terrain\] stones: a stones course needs policy \"footholds\""):
        from_dict({"terrain": {"kind": "stones"}})
    with pytest.raises(ValueError, match=r"\[control\] policy: 'footholds' aims at stepping stones"):
        from_dict({"control": {"policy": "footholds"}})


# ----------------------------------------------------------------------------------------------
# the planner
# ----------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def planner():
    return Footholds("iterative", P, horizon=2).warm_up()


def test_the_one_feasible_sequence_is_found(planner):
    plan = planner.plan(1.0, 5.0, Course.of(ONE_WAY, 0.02), target_height=1.0, target_speed=5.0)
    assert plan.status == FootholdStatus.FOOTHOLD and plan.stones == (1, 3)
    assert plan.candidates == 3 and plan.feasible == 1
    assert min(plan.margins) > 0.1  # measured 0.125 m and 0.115 m
    assert plan.touchdown_angle == plan.touchdown_angles[0] and len(plan.k_d) == 2


def test_the_plans_feet_are_where_the_map_puts_them(planner):
    """Hop 1 of a plan applied to the model map from the same apex lands its foot at the planned
    point (the flight is exact on every map) and its next apex at the planned one."""
    plan = planner.plan(1.0, 5.0, Course.of(ONE_WAY, 0.02), target_height=1.0, target_speed=5.0)
    step = slipmaps.apex_return(
        "iterative", P.with_(k_c=plan.k_c[0], k_d=plan.k_d[0]), 1.0, 5.0, plan.touchdown_angle, ground=0.0
    )
    assert abs(step.values["foot_x"] - plan.feet[0]) < 1e-12  # measured 0
    assert abs(step.next_apex_height - plan.apex_heights[0]) < 1e-12
    assert abs(step.next_apex_speed - plan.apex_speeds[0]) < 1e-12


def test_the_baseline_aims_the_deadbeat_at_a_stones_centre():
    base = Footholds("iterative", P, horizon=0)
    course = Course.of(ONE_WAY, 0.02)
    plan = base.plan(1.0, 5.0, course, target_height=1.0, target_speed=5.0)
    k = plan.stones[0]
    assert plan.status == FootholdStatus.FOOTHOLD and k == 1
    assert abs(plan.feet[0] - 0.5 * (course.lo[k] + course.hi[k])) < 1e-6  # the solve's tolerance
    assert abs(plan.apex_heights[0] - 1.0) < 1e-6  # and the next apex at the target height


def test_no_stone_in_reach_is_one_line():
    reach = r"^stones: no stone within reach of the apex at x = 0 m: the first foot lands within about "
    reach += r"\[0\.421, 1\.68\] m"
    with pytest.raises(CourseError, match=reach) as err:
        slipmaps.footholds("iterative", P, {"height": 1.0, "speed": 5.0}, [[0.0, 0.3, 0.0], [4.0, 5.0, 0.0]])
    assert "\n" not in str(err.value)
    with pytest.raises(ValueError, match="apex must have the keys height, speed"):
        slipmaps.footholds("iterative", P, {"height": 1.0}, ONE_WAY)


def test_geyer_plans_with_the_angle_alone():
    plan = slipmaps.footholds(
        "geyer", P.with_(k=P.k_c), {"height": 1.0, "speed": 5.0}, ONE_WAY, margin=0.02, target_speed=5.0
    )
    assert plan.ok and plan.stones[0] == 1 and plan.k_c == plan.k_d == (P.k_c, P.k_c)


# ----------------------------------------------------------------------------------------------
# runs
# ----------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def example_runs():
    return {h: slipmaps.run(EXAMPLE, horizon=h) for h in (1, 2)}


def test_horizon_2_hops_the_course_where_horizon_1_misses(example_runs):
    one, two = example_runs[1], example_runs[2]
    assert not two.fell and len(two) == 14
    assert one.fell and one.steps[-1]["plant_status"] == "MISSED"
    assert set(two.column("plan_status").tolist()) <= {5}  # FOOTHOLD every step


def test_a_miss_is_recorded_as_such(example_runs):
    r = example_runs[1]
    n = len(r) - 1
    assert r.status == f"fell at step {n}: MISSED"
    assert int(r.batch.codes["plant_status"][0, n]) == MISSED
    assert r.column("stone")[n] == -1 and r.column("stone")[:n].min() >= 0
    foot = r.column("foot_position")[n]
    assert r.scenario.stones.landing(foot)[0] == -1  # the foot outside every usable part
    assert math.isnan(r.column("next_apex_height")[n])
    cols = r.columns()
    assert cols["plant_status"][n] == "MISSED" and cols["plant_status_code"][n] == MISSED


def test_the_flown_feet_are_the_planned_ones_on_the_exact_plant(example_runs):
    r = example_runs[2]
    error = np.abs(r.column("foot_position") - r.column("planned_foot"))
    assert error.size == 14 and error.max() < 1e-9  # measured 1.8e-15 m: the flight is exact
    # the ground under each touchdown is the stone's the foot landed on (to the round-off of the
    # plant's relative grounds summed: measured 1e-17 m)
    k = r.column("stone").astype(int)
    assert np.allclose(r.column("ground"), r.scenario.stones.heights[k], rtol=0.0, atol=1e-12)


def test_the_robots_terrain_is_the_stones_with_pits():
    from slipmaps.runtime.control.robot_plant import STONE_PIT, stones_terrain

    c = Course.of([[0.5, 1.0, 0.1], [1.5, 2.0, -0.05]])
    t = stones_terrain(c)
    x = np.array([0.2, 0.75, 1.25, 1.75, 2.5])
    assert np.allclose(t.height_at(x), [0.0, 0.1, -0.05 - STONE_PIT, -0.05, -0.05 - STONE_PIT])
