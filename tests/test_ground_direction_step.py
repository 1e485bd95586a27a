"""The three additions of the calling convention, in every map, the exact simulator and the Jacobians.

- Backward running (a signed apex speed): the model is symmetric under x -> -x, (q_th, q_thd) ->
  (-q_th, -q_thd), so a step toward -x with the mirrored touchdown angle is the mirror image of the
  step toward +x: every output that is odd under the mirror (the index's ``odd`` flag: leg angles
  and their rates, horizontal speeds and distances, angular impulses) changes sign, the others
  keep their value, and a Jacobian entry changes sign when exactly one of its output and input is
  odd. Measured: bitwise equal for every map (the formulas are odd in the angle and its rate).
- ``ground``: the touchdown ground ``ground`` higher than the ground under the apex. The stance
  does not see it, the descent does: a step from apex height h onto ground g is the step from h - g
  onto flat ground (every output, ``foot_y = g - h`` included). Against the solve_ivp reference
  with the same ground.
- ``step_length``, ``foot_x``, ``foot_y``: against the geometry of the reference's step.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
from slipmaps.generated import maps_index
from slipmaps.generated.status import Status
from slipmaps.runtime.api import names
from slipmaps.runtime.exact import reference as sim

P = slipmaps.HUMAN_RUNNER
VS = P.with_(k_d=24_000.0)
NAMES = [m.name for m in slipmaps.maps()]
HALVES = [h.name for h in slipmaps.runtime.api.index.halves()]

#: Parity of every output under the mirror, from the index (outputs by the results' names, and every
#: map's extras).
ODD = {
    names.public(r["name"])
    for r in (*maps_index.STANCE_OUTPUTS, *maps_index.APEX_OUTPUTS, *maps_index.HALF_OUTPUTS)
    if r["odd"]
}
ODD |= {e["name"] for row in (*maps_index.MAPS, *maps_index.HALVES) for e in row["extras"] if e["odd"]}
#: ... and of every input a Jacobian has.
ODD_INPUTS = {"apex_speed", "touchdown_angle", "retraction_rate", "q_th_td", "q_thd_td"}


def _params(name: str) -> slipmaps.SlipParams:
    info = slipmaps.runtime.api.index.lookup(name)
    return P if "constant_stiffness" in info.requires else VS


def _sign(name: str) -> float:
    return -1.0 if name in ODD else 1.0


def _assert_mirror(forward: dict, backward: dict) -> None:
    assert set(forward) == set(backward)
    for key, value in forward.items():
        assert backward[key] == _sign(key) * value, (key, value, backward[key])


def test_the_index_marks_the_odd_outputs():
    assert {
        "next_apex_speed",
        "step_length",
        "foot_x",
        "liftoff_q_th",
        "liftoff_q_thd",
        "bottom_q_th",
        "P_c",
    } <= ODD
    assert not {"next_apex_height", "foot_y", "t_stance", "liftoff_q_r", "liftoff_q_rd", "passes"} & ODD


@pytest.mark.parametrize("name", NAMES)
def test_running_backward_is_the_mirror_image_bitwise(name):
    params = _params(name)
    for h, v, th, ground in ((1.0, 5.0, 0.35, 0.0), (1.05, 3.0, 0.30, 0.04), (0.95, 6.5, 0.45, -0.05)):
        fwd = slipmaps.apex_return(name, params, h, v, th, ground=ground)
        bwd = slipmaps.apex_return(name, params, h, -v, -th, ground=ground)
        assert fwd.ok and bwd.ok and fwd.next_apex_speed > 0 > bwd.next_apex_speed, (fwd.message, bwd.message)
        _assert_mirror(fwd.values, bwd.values)
    td = (1.0, -1.5, 0.35, -4.5)
    fwd = slipmaps.stance(name, params, td)
    bwd = slipmaps.stance(name, params, (td[0], td[1], -td[2], -td[3]))
    assert fwd.ok and bwd.ok
    _assert_mirror(fwd.values, bwd.values)
    batch = slipmaps.apex_return_batch(name, params, 1.0, np.array([5.0, -5.0]), np.array([0.35, -0.35]))
    assert batch.ok.all() and batch["step_length"][1] == -batch["step_length"][0]


@pytest.mark.parametrize("name", NAMES)
def test_the_jacobians_mirror_with_their_parities(name):
    params = _params(name)
    fwd = slipmaps.apex_return_jacobian(name, params, 1.0, 5.0, 0.35, ground=0.02)
    bwd = slipmaps.apex_return_jacobian(name, params, 1.0, -5.0, -0.35, ground=0.02)
    assert fwd.ok and bwd.ok and fwd.inputs == bwd.inputs
    signs = np.array(
        [[_sign(o) * (-1.0 if i in ODD_INPUTS else 1.0) for i in fwd.inputs] for o in fwd.outputs]
    )
    np.testing.assert_array_equal(bwd.matrix, signs * fwd.matrix)
    td = (1.0, -1.5, 0.35, -4.5)
    fwd = slipmaps.stance_jacobian(name, params, td)
    bwd = slipmaps.stance_jacobian(name, params, (td[0], td[1], -td[2], -td[3]))
    signs = np.array(
        [[_sign(o) * (-1.0 if i in ODD_INPUTS else 1.0) for i in fwd.inputs] for o in fwd.outputs]
    )
    np.testing.assert_array_equal(bwd.matrix, signs * fwd.matrix)


@pytest.mark.parametrize("name", HALVES)
def test_the_half_maps_mirror_bitwise(name):
    params = VS
    start = (
        (1.0, -1.5, 0.35, -4.5)
        if slipmaps.runtime.api.index.get_half(name).start == "touchdown"
        else (0.88, 0.0, -0.05, -5.0)
    )
    fwd = slipmaps.half_stance(name, params, start)
    bwd = slipmaps.half_stance(name, params, (start[0], start[1], -start[2], -start[3]))
    assert fwd.ok and bwd.ok, (fwd.message, bwd.message)
    _assert_mirror({k.replace("end_", "liftoff_"): v for k, v in fwd.values.items()},
                   {k.replace("end_", "liftoff_"): v for k, v in bwd.values.items()})  # fmt: skip


@pytest.mark.parametrize("name", NAMES)
def test_a_vertical_hop_is_a_valid_step_that_stays_vertical(name):
    """Apex speed 0 and a vertical leg: the step stays in place (speed, angles and length exactly 0)."""
    res = slipmaps.apex_return(name, _params(name), 1.1, 0.0, 0.0)
    assert res.ok, res.message
    assert res.next_apex_speed == 0.0 and res.step_length == 0.0 and res.foot_x == 0.0
    assert res.liftoff_q_th == 0.0 and res.liftoff_q_thd == 0.0


@pytest.mark.parametrize("name", NAMES)
def test_a_step_onto_other_ground_is_the_step_from_the_apex_above_it(name):
    """h onto ground g = h - g onto flat ground, every output (foot_y = g - h both ways). Measured:
    equal within 3 ulp of the apex height (h - g is rounded)."""
    params = _params(name)
    for h, g in ((1.1, 0.1), (0.92, -0.08), (1.3, 0.3)):
        up = slipmaps.apex_return(name, params, h, 5.0, 0.35, ground=g)
        flat = slipmaps.apex_return(name, params, h - g, 5.0, 0.35)
        assert up.ok and flat.ok
        for key, value in flat.values.items():
            assert up[key] == pytest.approx(value, rel=1e-12, abs=1e-13), key


def test_a_step_up_the_apex_cannot_clear_is_apex_too_low():
    res = slipmaps.apex_return("exact", P, 1.0, 5.0, 0.35, ground=0.1)  # touchdown at 1.04 m > 1.0 m
    assert res.status == Status.APEX_TOO_LOW
    batch = slipmaps.apex_return_batch("geyer", P, 1.0, 5.0, 0.35, ground=np.array([0.0, 0.1, math.nan]))
    assert list(batch["status"]) == [Status.OK, Status.APEX_TOO_LOW, Status.INVALID_INPUT]


@pytest.mark.parametrize("ground", [-0.2, -0.05, 0.0, 0.03])
@pytest.mark.parametrize("speed", [3.0, -5.0])
def test_the_exact_map_on_uneven_ground_is_the_solve_ivp_reference(ground, speed):
    """The compiled exact map (the generated composition) against solve_ivp with the same ground and
    signed speed. Measured: within 3.6e-15 relative (times within 4.4e-16 s)."""
    angle = math.copysign(0.35, speed)
    got = slipmaps.apex_return("exact", P, 1.05, speed, angle, ground=ground)
    ref = sim.simulate_step(P, 1.05, speed, angle, ground=ground)
    scipy = slipmaps.apex_return("exact", P, 1.05, speed, angle, ground=ground, method="scipy")
    assert got.ok and ref.ok and scipy.ok
    want = {names.public(k): v for k, v in sim.step_values(ref).items()}  # the results' names
    for key, value in got.values.items():
        assert value == pytest.approx(want[key], rel=1e-12, abs=1e-13), key
        assert scipy[key] == want[key], key


def test_the_step_geometry_is_the_reference_steps():
    """step_length = the apex's travel to the touchdown + the body's travel over the foot + the
    ascent's travel; foot_x the first part plus the leg's reach q_r_td sin(q_th_td)."""
    for speed, angle, ground in ((5.0, 0.35, 0.0), (3.0, 0.3, 0.05), (-4.0, -0.4, -0.1)):
        ref = sim.simulate_step(P, 1.05, speed, angle, ground=ground)
        assert ref.ok
        over_foot = -ref.liftoff[0] * math.sin(ref.liftoff[2]) + ref.touchdown[0] * math.sin(ref.touchdown[2])
        length = speed * ref.t_descent + over_foot + ref.dx_ascent
        assert ref.step_length == pytest.approx(length, rel=1e-12)
        assert ref.foot_x == pytest.approx(speed * ref.t_descent + P.q_r_td * math.sin(angle), rel=1e-12)
        assert ref.foot_y == ground - 1.05
        got = slipmaps.apex_return("exact", P, 1.05, speed, angle, ground=ground)
        assert got.step_length == pytest.approx(length, rel=1e-12)
        assert math.copysign(1.0, got.step_length) == math.copysign(1.0, speed)
