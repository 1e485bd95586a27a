"""The simple variable-stiffness map ``geyer-vs`` (report section 5.1, derive/maps/geyer_vs.py) and the
bottom leg length of (153) (kernel ``bottom_quartic``).

Tolerances are measured (see each docstring). Accuracy over k_d/k_c is measured by
``slipmaps accuracy`` (docs/stiffness.md), not here.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest
import slipmaps
from slipmaps import HUMAN_RUNNER, SlipParams, Status
from slipmaps.generated.geyer_vs import bottom_quartic

MAP = "geyer-vs"
M, L0, K, G = HUMAN_RUNNER.m, HUMAN_RUNNER.l0, HUMAN_RUNNER.k_c, HUMAN_RUNNER.g_s


def _params(ratio: float) -> SlipParams:
    return SlipParams(M, L0, k_c=K, k_d=K * ratio)


def _touchdowns() -> np.ndarray:
    rng = np.random.default_rng(7)
    n = 40
    return np.column_stack(
        [
            rng.uniform(0.95, 1.0, n) * L0,
            -rng.uniform(0.5, 2.5, n),
            rng.uniform(0.1, 0.45, n),
            -rng.uniform(2.0, 6.0, n),
        ]
    )


def test_eq98_energy_continuity_at_equal_stiffness_is_geyers_map():
    """k_c = k_d and continuity = energy: no energy jump (97), the second half continues the first
    one's solution, so the map is Geyer et al.'s (measured: equal to 1e-15 relative)."""
    td = _touchdowns()
    vs = slipmaps.stance_batch(MAP, HUMAN_RUNNER, td)
    geyer = slipmaps.stance_batch("geyer", HUMAN_RUNNER, td)
    assert np.array_equal(vs["status"], geyer["status"]) and vs.ok.sum() >= 30
    for key in ("t_stance", "bottom_q_r", "bottom_q_th", "liftoff_q_rd", "liftoff_q_th", "liftoff_q_thd"):
        np.testing.assert_allclose(vs[key][vs.ok], geyer[key][vs.ok], rtol=1e-13, atol=1e-14, err_msg=key)


@pytest.mark.parametrize("ratio", [0.8, 1.25])
def test_eq110_continuity_of_the_leg_length_at_the_bottom(ratio):
    """q_r just before and just after the bottom: continuous for ``energy`` ((110) holds by itself)
    and ``constrained`` ((111)); for ``report`` ((103)-(104) with the touchdown energy (27)) it jumps
    (the report's Figure 7, middle: measured 1.0-2.1 cm on three touchdowns for k_d/k_c 0.8-1.25,
    1.3-1.8 cm even at k_c = k_d: the energy (27) has the cos q_th of the gravity potential that the
    small-angle energy (8) of the first half drops)."""
    td = (1.0, -1.5, 0.3, -4.0)
    jumps = {}
    for continuity in ("report", "constrained", "energy"):
        res = slipmaps.stance(MAP, _params(ratio), td, continuity=continuity)
        assert res.ok, res.message
        t_b = res["t_bottom"]
        _, states, status = slipmaps.trajectory(
            MAP, _params(ratio), td, np.array([t_b * (1 - 1e-12), t_b * (1 + 1e-12)]), continuity=continuity
        )
        assert status == Status.OK
        jumps[continuity] = abs(states[1, 0] - states[0, 0])
        assert states[0, 0] == pytest.approx(res["bottom_q_r"], abs=1e-10)
    assert jumps["energy"] < 1e-9 and jumps["constrained"] < 1e-9, jumps
    assert jumps["report"] > 5e-3, jumps


def test_eq97_energy_jump_moves_the_next_apex_the_right_way():
    """A stiffer decompression (k_d > k_c) stores energy at the bottom (97): the next apex is higher,
    and a softer one lower, in the map as in the exact simulator."""
    heights = {}
    for ratio in (0.9, 1.0, 1.1):
        for name in (MAP, "exact"):
            res = slipmaps.apex_return(name, _params(ratio), 1.0, 5.0, 0.35)
            assert res.ok, (name, res.message)
            heights[name, ratio] = res["next_apex_height"]
    for name in (MAP, "exact"):
        assert heights[name, 0.9] < heights[name, 1.0] < heights[name, 1.1], heights


def test_soft_decompression_is_recompression_not_nan():  # also the iterative map
    """k_d so soft that the bottom lies above the centre a_ba of the second half's oscillation: the
    k_d spring cannot start extending the leg, RECOMPRESSION (the exact simulator's status there)."""
    params, td = _params(0.2), (1.0, -0.8, 0.05, -0.5)  # a slow, nearly vertical stance
    res = slipmaps.stance(MAP, params, td)
    assert res.status == Status.RECOMPRESSION and np.all(np.isnan(res.liftoff))
    assert slipmaps.stance("exact", params, td).status == Status.RECOMPRESSION
    # the converging iterative map and its decompression half check the same condition
    assert slipmaps.stance("iterative", params, td).status == Status.RECOMPRESSION


@pytest.mark.parametrize(
    ("p", "energy", "expected_real_roots"),
    [
        (40.0, 785.0, 2),  # two positive roots, both below l0: the smaller one is the bottom
        (5.0, 900.0, 2),  # one root below l0, one above
        (5.0, 30000.0, 4),  # four real roots, two negative
    ],
)
def test_eq153_quartic_root_is_the_smallest_positive_one(p, energy, expected_real_roots):
    """The kernel picks the physical root of (153): real, in (0, l0], the smallest positive one (the
    compressing side of the convex potential); np.roots lists them all (agreement measured 1e-15)."""
    roots = np.roots([K / 2, M * G - K * L0, K * L0**2 / 2 - energy, 0.0, p**2 / (2 * M)])
    real = np.sort(roots[np.abs(roots.imag) < 1e-12].real)
    assert len(real) == expected_real_roots
    q_r_b, status = bottom_quartic(p, energy, M, L0, K, G)
    assert status == Status.OK
    assert q_r_b == pytest.approx(real[real > 0][0], rel=1e-12)
    assert 0 < q_r_b <= L0


def test_eq153_no_root_is_a_status():
    """Energy below the minimum of the potential: no bottom, NO_REAL_SOLUTION (never NaN with OK)."""
    q_r_b, status = bottom_quartic(40.0, 700.0, M, L0, K, G)
    assert status == Status.NO_REAL_SOLUTION and np.isnan(q_r_b)


def test_constant_stiffness_maps_name_the_variable_stiffness_ones():
    """k_c != k_d: a constant-stiffness map refuses, and its message names every map that accepts it."""
    with pytest.raises(ValueError, match="geyer-vs") as err:
        slipmaps.apex_return("geyer", _params(1.25), 1.0, 5.0, 0.35)
    for name in ("iterative", "iterative-report", "exact"):
        assert name in str(err.value)


def test_example_choose_kd_hits_the_target_apex_in_the_exact_simulator():
    """examples/choose_kd.py: k_d chosen on the map reaches the target apex in the exact simulator
    (measured: 1e-6 m from the bottom state with iterative-decompression, 1.8-2.6e-4 m planned at
    the apex with geyer-vs, targets 0.95-1.05 m), in at most 4 Newton steps."""
    path = Path(__file__).resolve().parents[1] / "examples" / "choose_kd.py"
    spec = importlib.util.spec_from_file_location("choose_kd", path)
    example = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = example  # its dataclass looks its module up
    spec.loader.exec_module(example)
    bound = {"iterative-decompression": 1e-5, "geyer-vs": 5e-4}
    for target in (0.95, 1.05):
        for choice in example.choose(target):
            assert abs(choice.predicted - target) < example.TOL, choice
            assert abs(choice.exact - target) < bound[choice.planner], choice
            assert choice.steps <= 4, choice
