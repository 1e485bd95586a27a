"""The leg damping ``c`` in the map ``iterative`` and its halves (derive/maps/iterative.py).

The damper's force -c p_r/m enters F_r at the nodes at the previous Picard pass's p_r (the work
form p_r^2 = 2 m int F_r holds for any F_r); option ``liftoff`` is the exact map's. At c = 0 every
output is the lossless map's, bit for bit (tests/data/iterative_c0.json, written before the damper
entered: tests/iterative_c0.py). The ground truth is the exact map with the same c and liftoff
(tests/test_damping.py checks it against an independent integration).
"""

from __future__ import annotations

import json
import math

import iterative_c0
import numpy as np
import pytest
import slipmaps
from slipmaps.generated.status import Status
from slipmaps.runtime.api.params import HUMAN_RUNNER, SlipParams
from test_geyer_damped import STEPS

TOUCHDOWN = (1.0, -1.2, 0.35, -4.6)


def damped(ratio: float, p: SlipParams = HUMAN_RUNNER) -> SlipParams:
    """``p`` with the damping ratio c / (2 sqrt(k_c m))."""
    return p.with_(c=ratio * 2.0 * math.sqrt(p.k_c * p.m))


def _same_bits(before: list[str], now: list[str]) -> bool:
    """float.hex equal, but for the sign of an exact zero (module :func:`test_zero_damping...`)."""
    pairs = zip(before, now, strict=True)
    return all(b == n or float.fromhex(b) == float.fromhex(n) == 0.0 for b, n in pairs)


@pytest.mark.parametrize("liftoff", [None, "force", "length"])
def test_zero_damping_is_the_lossless_iteration_bit_for_bit(liftoff):
    """Stance, apex return, both halves and the Jacobians (but for c's own column) of every case of
    tests/iterative_c0.py (every node count, no pass, tolerances, the held zeroth iterate, k_c != k_d
    and q_r_lo < l0), against the stored float.hex: equal bits. One exception, the sign of an exact
    zero: d liftoff_q_r / d apex input was a structural 0.0 and is now a sum of products with the
    liftoff's branch (0 at c = 0), which can be -0.0 (equal as numbers; 0 of the 56 cases' values
    and 2 to 6 entries of the apex Jacobians' liftoff_q_r row, measured)."""
    stored = json.loads(iterative_c0.DATA.read_text())
    got = iterative_c0.outputs(**({} if liftoff is None else {"liftoff": liftoff}))
    assert len(got) == len(stored) == 56
    for before, now in zip(stored, got, strict=True):
        where = (before["map"], before["params"], before["options"])
        assert now.keys() == before.keys(), where
        for key in ("stance", "apex", "half"):
            assert now.get(key) == before.get(key), (where, key)  # values: every bit
        for key in ("stance_jacobian", "apex_jacobian"):
            if key in before:
                assert now[key]["inputs"] == before[key]["inputs"], where
                assert _same_bits(before[key]["matrix"], now[key]["matrix"]), (where, key)


def next_apex_errors(p: SlipParams, liftoff: str, **options) -> np.ndarray:
    """Relative next-apex errors of ``iterative`` against ``exact`` (the larger of height's and
    speed's) over the 45 human-runner steps of tests/test_geyer_damped.py, where the exact step is
    OK (the iterative map then is too)."""
    h, v, a = (np.array(x) for x in zip(*STEPS, strict=True))
    exact = slipmaps.apex_return_batch("exact", p, h, v, a, liftoff=liftoff)
    approx = slipmaps.apex_return_batch("iterative", p, h, v, a, liftoff=liftoff, **options)
    np.testing.assert_array_equal(approx.status, exact.status)
    ok = exact.status == Status.OK
    assert ok.sum() >= 43, np.bincount(exact.status)
    errors = [np.abs(approx[n][ok] / exact[n][ok] - 1.0) for n in ("next_apex_height", "next_apex_speed")]
    return np.maximum(*errors)


#: (liftoff, damping ratio) -> measured (mean, max) relative next-apex error at the default options
#: (4 nodes, 6 passes, Geyer's zeroth iterate) over the 45 steps; the bound asserted is a fifth
#: above. The issue's target, a mean of 1e-5 (1e-3 %), holds but for "length" at 20 % of the
#: critical damping, where the 4-node quadrature of the pull phase near liftoff is the floor
#: (test_length_liftoff_at_strong_damping_needs_more_nodes). Two of those 45 exact steps end
#: LIFTOFF_DOWNWARD there (the leg pulls the body down before l0), as the iterative map's do.
MEASURED = {
    ("force", 0.0): (3.86e-6, 7.18e-6),
    ("force", 0.02): (3.17e-6, 6.93e-6),
    ("force", 0.05): (2.43e-6, 6.85e-6),
    ("force", 0.1): (1.88e-6, 7.28e-6),
    ("force", 0.2): (3.82e-6, 1.44e-5),
    ("length", 0.02): (3.85e-6, 9.18e-6),
    ("length", 0.05): (4.51e-6, 1.42e-5),
    ("length", 0.1): (8.00e-6, 3.12e-5),
    ("length", 0.2): (2.77e-5, 1.47e-4),
}


@pytest.mark.parametrize(("liftoff", "ratio"), sorted(MEASURED))
def test_damped_next_apex_against_the_exact_damped_map(liftoff, ratio):
    errors = next_apex_errors(damped(ratio), liftoff)
    mean, worst = MEASURED[liftoff, ratio]
    assert errors.mean() <= 1.2 * mean, errors.mean()
    assert errors.max() <= 1.2 * worst, errors.max()
    if (liftoff, ratio) != ("length", 0.2):
        assert errors.mean() <= 1e-5  # the target


def test_length_liftoff_at_strong_damping_needs_more_nodes():
    """ "length" at 20 % of the critical damping: 6 nodes (6 passes) bring the mean below the target
    (measured 8.2e-7, max 5.2e-6), 12 passes at 4 nodes do not (2.76e-5: the quadrature's floor)."""
    p = damped(0.2)
    assert next_apex_errors(p, "length", nodes="6").mean() < 1e-6
    assert next_apex_errors(p, "length", iterations=12).mean() > 2e-5


def _stance(p: SlipParams, w: np.ndarray, liftoff: str) -> np.ndarray:
    res = slipmaps.stance("iterative", p.with_(k_c=w[4], k_d=w[5], c=w[6]), w[:4], liftoff=liftoff)
    assert res.status == Status.OK
    return np.array(list(res.values.values()))


@pytest.mark.parametrize(
    ("params", "liftoff"),
    [
        (damped(0.1), "force"),
        (damped(0.1), "length"),
        (damped(0.2, HUMAN_RUNNER.with_(k_d=24_000.0, q_r_lo=0.98)), "force"),
        (damped(0.05, HUMAN_RUNNER.with_(q_r_lo=0.97)), "force"),
    ],
    ids=["10%", "10%-length", "20%-kd-qrlo", "5%-qrlo"],
)
def test_damped_jacobian_matches_central_differences(params, liftoff):
    """Every column but q_r_td (at l0: no q_r + h), c's included: the derivatives through the passes
    of the damper's term, and with "force" of the leg force's zero (or q_r_lo first) against central
    differences, h = 1e-6 of each input's scale (l0, sqrt(g l0), 1 rad, sqrt(g/l0), k_c, k_d, the
    critical damping). Measured: 7.2e-11 to 4.0e-9 of each column's largest entry."""
    p = params
    jac = slipmaps.stance_jacobian("iterative", p, TOUCHDOWN, liftoff=liftoff)
    assert jac.status == Status.OK and jac.inputs[-1] == "c"
    w0 = np.array([*TOUCHDOWN, p.k_c, p.k_d, p.c])
    critical = 2.0 * math.sqrt(p.k_c * p.m)
    scale = np.array([p.l0, math.sqrt(p.g_s * p.l0), 1.0, math.sqrt(p.g_s / p.l0), p.k_c, p.k_d, critical])
    worst = 0.0
    for j in range(1, 7):
        step = np.zeros(7)
        step[j] = 1e-6 * scale[j]
        fd = (_stance(p, w0 + step, liftoff) - _stance(p, w0 - step, liftoff)) / (2.0 * step[j])
        column = jac.matrix[:, j]
        worst = max(worst, float(np.max(np.abs(fd - column)) / np.max(np.abs(column))))
    assert worst < 3e-8, worst


def test_force_liftoff_is_where_the_leg_force_falls_to_zero():
    """liftoff "force": the leg force k_d (l0 - q_r) - c q_rd at the liftoff state is ~0 (the end
    length from the previous pass's work, the state from the last: measured 7.6e-4 N at 10 % of the
    critical damping, of k_d l0 = 2e4 N; 20 passes: 2e-13 N), the liftoff below l0 as the exact
    map's (measured 2.8e-8 m apart); with q_r_lo before the force's zero, at q_r_lo."""
    p = damped(0.1)
    res = slipmaps.stance("iterative", p, TOUCHDOWN)
    exact = slipmaps.stance("exact", p, TOUCHDOWN)
    q_r, q_rd = res.values["liftoff_q_r"], res.values["liftoff_q_rd"]
    assert abs(p.k_d * (p.l0 - q_r) - p.c * q_rd) < 2e-3
    assert q_r < p.l0 - 0.01 and abs(q_r - exact.values["liftoff_q_r"]) < 1e-6
    more = slipmaps.stance("iterative", p, TOUCHDOWN, iterations=20).values
    assert abs(p.k_d * (p.l0 - more["liftoff_q_r"]) - p.c * more["liftoff_q_rd"]) < 1e-9
    short = p.with_(q_r_lo=0.97)
    assert slipmaps.stance("iterative", short, TOUCHDOWN).values["liftoff_q_r"] == short.q_r_lo
    length = slipmaps.stance("iterative", p, TOUCHDOWN, liftoff="length")
    assert length.values["liftoff_q_r"] == p.l0 and length.values["t_stance"] > res.values["t_stance"]


@pytest.mark.parametrize("liftoff", ["force", "length"])
def test_damped_halves_compose_into_the_whole_map(liftoff):
    """Compression half, then decompression half from its bottom: the whole damped stance (the
    whole map's decompression starts from Geyer's liftoff, the half's from the held bottom state;
    measured 2.8e-7 relative apart at 10 % of the critical damping, 6 passes)."""
    p = damped(0.1)
    whole = slipmaps.stance("iterative", p, TOUCHDOWN, liftoff=liftoff)
    c = slipmaps.half_stance("iterative-compression", p, TOUCHDOWN)
    d = slipmaps.half_stance("iterative-decompression", p, c["end"], liftoff=liftoff)
    assert whole.ok and c.ok and d.ok
    assert c["end"] == whole.bottom and c["t_half"] == whole.t_bottom
    assert d["end"] == pytest.approx(whole.liftoff, rel=1e-6, abs=1e-8)


def test_bad_damping_and_liftoff_are_refused_in_one_line():
    cases = [
        (lambda: HUMAN_RUNNER.with_(c=-1.0), "c must be finite and non-negative"),
        (
            lambda: slipmaps.stance("iterative", damped(0.1), TOUCHDOWN, liftoff="pull"),
            "option 'liftoff' must be one of 'force', 'length'",
        ),
        (
            lambda: slipmaps.half_stance("iterative-compression", damped(0.1), TOUCHDOWN, liftoff="force"),
            "has no option 'liftoff'",
        ),
        (lambda: slipmaps.apex_return("iterative-report", damped(0.1), 1.0, 5.0, 0.35), "does not model c"),
    ]
    for call, message in cases:
        with pytest.raises(ValueError, match=message) as err:
            call()
        assert "\n" not in str(err.value)
