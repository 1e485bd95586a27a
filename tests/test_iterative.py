"""The converging form of Schwind and Koditschek's iteration (map ``iterative``, derive/maps/iterative.py).

Tolerances are measured (see each docstring).
"""

from __future__ import annotations

import kernels
import numpy as np
import pytest
import slipmaps
from slipmaps.derive.maps import iterative as d_iterative
from slipmaps.derive.maps import quadrature_helpers
from slipmaps.derive.symbols import k_c, k_d
from slipmaps.generated.status import Status
from slipmaps.runtime.api import index
from slipmaps.runtime.api.params import HUMAN_RUNNER, SlipParams


def _apex_points():
    h, v, a = np.meshgrid([1.0, 1.05], [3.0, 4.5, 6.0], [0.3, 0.4, 0.5], indexing="ij")
    return h.ravel(), v.ravel(), a.ravel()


@pytest.mark.parametrize("n", [1, 2, 3, 4, 6])
def test_eq41_gauss_rule_in_u_integrates_polynomials(n):
    """The n-node rule on [0, 1] is exact to degree 2n - 1; the collocation matrices to degree n - 1."""
    r = quadrature_helpers.rule(n)
    u = np.array(r.nodes, dtype=float)
    for deg in range(2 * n):
        assert abs(np.dot(np.array(r.w, dtype=float), u**deg) - 1 / (deg + 1)) < 1e-15
    S, S1 = np.array(r.S, dtype=float), np.array(r.S1, dtype=float)
    for deg in range(n):
        assert np.allclose(S @ u**deg, u ** (deg + 1) / (deg + 1), atol=1e-15)
        assert np.allclose(S1 @ u**deg, u ** (deg + 2) / (deg + 2), atol=1e-15)


def test_eq41_one_node_is_the_mean_value_point():
    """One node: u = 1/2, weight 1, i.e. sigma = q_r_b + (x - q_r_b)/4 = 3/4 q_r_b + 1/4 x of (41)."""
    r = quadrature_helpers.rule(1)
    assert float(r.nodes[0]) == 0.5 and float(r.w[0]) == 1.0


@pytest.mark.parametrize("stiffness", [k_c, k_d])
def test_eq30_eq32_u_rates_are_regular_at_the_bottom(stiffness):
    """(30)-(32) in u with the work form of p_r: no negative power of u is left."""
    for rate in d_iterative.u_rates(stiffness):
        assert d_iterative._U not in rate.free_symbols


@pytest.mark.parametrize("ratio", [0.8, 1.0, 1.25])
def test_eq114_eq151_variable_stiffness_next_apex_within_measured_bound(ratio):
    """k_d/k_c from 0.8 to 1.25 on human-runner steps: next apex within 0.01 % of the exact one
    (target 2 %; measured on the 243-point human-runner grid for k_d/k_c 0.6-1.5: mean 2e-4 %,
    max 0.0022 %)."""
    params = SlipParams(HUMAN_RUNNER.m, HUMAN_RUNNER.l0, k_c=20000.0, k_d=20000.0 * ratio)
    h, v, a = _apex_points()
    approx = slipmaps.apex_return_batch("iterative", params, h, v, a)
    exact = slipmaps.apex_return_batch("exact", params, h, v, a)
    ok = exact.ok
    assert ok.sum() >= 12 and np.all(approx.ok[ok])
    err = np.hypot(
        approx["next_apex_height"] - exact["next_apex_height"],
        approx["next_apex_speed"] - exact["next_apex_speed"],
    ) / np.hypot(exact["next_apex_height"], exact["next_apex_speed"])
    assert np.max(err[ok]) < 1e-4


def test_more_passes_and_nodes_approach_the_exact_stance():
    """n = 2, 4, 6 at 4 nodes, then 6 nodes at 8 passes: the liftoff error decreases each time."""
    h, v, a = _apex_points()
    exact = slipmaps.apex_return_batch("exact", HUMAN_RUNNER, h, v, a)
    errors = []
    for opts in ({"iterations": 2}, {"iterations": 4}, {"iterations": 6}, {"iterations": 8, "nodes": "6"}):
        approx = slipmaps.apex_return_batch("iterative", HUMAN_RUNNER, h, v, a, **opts)
        errors.append(np.nanmax(np.abs(approx["liftoff"] - exact["liftoff"])))
    assert all(b < a for a, b in zip(errors, errors[1:], strict=False)), errors


def _zeroth_choices() -> tuple[str, ...]:
    return index.lookup("iterative").option("zeroth").choices


def test_zeroth_iterate_choices_are_every_map_not_itself_iterated_from_one():
    """Any declared map can start the iteration: every map without a ``zeroth`` option and without
    the leg damping c (the iteration adds the damper to a lossless guess) is a choice (derived from
    the declarations, derive/maps/__init__.py's starting_maps: a new map is one with no edit
    elsewhere), plus the held state."""
    maps = {m.name for m in slipmaps.maps() if m.name != "exact"}
    lossless = {n for n in maps if "c" not in index.lookup(n).params}
    assert lossless < maps  # geyer-damped takes c
    starters = {n for n in lossless if "zeroth" not in {o.name for o in index.lookup(n).options}}
    assert starters and starters < maps, (starters, maps)
    for name in ("iterative", "iterative-report", "iterative-compression", "iterative-report-compression"):
        assert set(index.lookup(name).option("zeroth").choices) == starters | {"held"}, name


def test_zeroth_iterate_does_not_matter_once_converged():
    """Every zeroth iterate (each map, the held touchdown state): the same limit (measured 1e-9).
    Scalar calls, one per point: a choice's batch form is the same kernel in a loop (the default's
    is tested with the batches), and compiling it for 18 points would cost more than the points."""
    kw = {"iterations": 100, "tol": 1e-13}

    def steps(zeroth: str) -> list:
        return [
            slipmaps.apex_return("iterative", HUMAN_RUNNER, *point, zeroth=zeroth, **kw)
            for point in zip(*_apex_points(), strict=True)
        ]

    ref = steps("geyer")
    assert sum(r.ok for r in ref) >= 12
    for zeroth in _zeroth_choices():
        other = steps(zeroth)
        assert [r.status for r in other] == [r.status for r in ref], zeroth
        assert (
            max(abs(o.next_apex_height - r.next_apex_height) for o, r in zip(other, ref, strict=True) if r.ok)
            < 1e-8
        ), zeroth


def test_soft_decompression_returns_a_status_not_nan():
    """k_d far too soft: the leg cannot extend back; a status for every row, never a NaN with OK."""
    params = SlipParams(HUMAN_RUNNER.m, HUMAN_RUNNER.l0, k_c=20000.0, k_d=500.0)
    h, v, a = _apex_points()
    res = slipmaps.apex_return_batch("iterative", params, h, v, a)
    assert not np.any(res.ok)
    assert set(np.unique(res["status"])) <= {
        int(Status.RECOMPRESSION),
        int(Status.NO_LIFTOFF),
        int(Status.IMAGINARY_MOMENTUM),
        int(Status.LIFTOFF_DOWNWARD),
    }
    assert np.all(np.isnan(res["next_apex_height"]))


@pytest.mark.parametrize("nodes", ["1", "2", "3", "4", "6"])
def test_eq41_node_loops_stop_at_the_node_count(nodes):
    """The value kernels loop to the largest node count and stop at the option's count (a trip count
    LLVM unrolls: derive/ir.py ``Kernel.unroll_nodes``), the derivative kernels loop to the count: at
    every node count both give the same next apex (measured: within 1.9e-15 of a row's largest value,
    300 states; the two kernels' expressions differ in their common subexpressions)."""
    import inspect

    from slipmaps.generated import iterative, iterative_jacobian

    bound = f"in range({max(d_iterative.NODE_COUNTS)}):"
    assert bound in inspect.getsource(iterative.schwind_compression.py_func)
    jvp = [f for n, f in vars(iterative_jacobian).items() if n.startswith("schwind_compression_jvp")]
    assert len(jvp) == 1 and bound not in inspect.getsource(jvp[0].py_func)
    rng = np.random.default_rng(5)
    h, v, a = rng.uniform(0.95, 1.1, 60), rng.uniform(2.0, 7.0, 60), rng.uniform(0.2, 0.45, 60)
    values = slipmaps.apex_return_batch("iterative", HUMAN_RUNNER, h, v, a, nodes=nodes)
    jacobian = slipmaps.apex_return_jacobian_batch("iterative", HUMAN_RUNNER, h, v, a, nodes=nodes)
    np.testing.assert_array_equal(values.status, jacobian.status)
    ok = values.ok
    assert ok.sum() >= 30
    for name in values.names:
        x, y = values[name][ok], jacobian.result[name][ok]
        scale = np.max([np.abs(values[n][ok]) for n in values.names], axis=0)
        assert np.max(np.abs(x - y) / scale) < 1e-14, name


def test_pass_bound_is_enforced():
    """iterations above the declared bound 100: the API refuses it, the kernel returns INVALID_INPUT."""
    from slipmaps.generated import iterative

    with pytest.raises(ValueError, match="iterations"):
        slipmaps.stance("iterative", HUMAN_RUNNER, (1.0, -1.0, 0.4, -4.0), iterations=101)
    p = HUMAN_RUNNER
    touchdown = dict(zip(("q_r_td", "q_rd_td", "q_th_td", "q_thd_td"), (1.0, -1.0, 0.4, -4.0), strict=True))
    base = {**touchdown, **p.values()}
    info = index.get("iterative")
    spec = info.kernels_for(info.resolve({"zeroth": "geyer"}))["stance"]  # zeroth: kernels per choice
    kernel = spec.functions()[0]
    assert kernel is iterative.iterative_stance_zeroth_geyer

    def status(**values) -> Status:
        """The kernel's status, its layouts filled by the index's names."""
        # nodes: the code of 4 nodes; liftoff: the code of "force"
        env = {**base, "nodes": 3.0, "tol": 0.0, "liftoff": 0.0, **values}
        return Status(kernels.call_layouts(kernel, spec.x, spec.p, spec.width, env)[-1])

    assert status(iterations=100.0) == Status.OK
    assert status(iterations=101.0) == Status.INVALID_INPUT


# ----------------------------------------------------------------------------------------------
# The half-stance maps (report 5.2.1, 5.2.2): iterative-compression, iterative-decompression
# ----------------------------------------------------------------------------------------------
VARIABLE = SlipParams(m=80.0, l0=1.0, k_c=20_000.0, k_d=25_000.0)
TOUCHDOWNS = [(1.0, -1.5, 0.35, -4.5), (0.98, -2.0, 0.3, -5.0), (1.0, -0.8, 0.25, -3.0)]


@pytest.mark.parametrize("td", TOUCHDOWNS)
def test_eq123_eq143_halves_compose_into_the_whole_map(td):
    """Compression half, then decompression half from its bottom: the whole map's stance (measured:
    4e-12 to 4.4e-10 relative; the whole map's decompression starts from Geyer's liftoff, the half
    from the held bottom state, and 6 passes make the two zeroth iterates agree to that)."""
    whole = slipmaps.stance("iterative", VARIABLE, td)
    c = slipmaps.half_stance("iterative-compression", VARIABLE, td)
    d = slipmaps.half_stance("iterative-decompression", VARIABLE, c["end"])
    assert whole.ok and c.ok and d.ok, (whole.message, c.message, d.message)
    assert c["end"] == whole.bottom and c["t_half"] == whole.t_bottom
    assert d["end"] == pytest.approx(whole.liftoff, rel=2e-9, abs=1e-10)
    assert c["t_half"] + d["t_half"] == pytest.approx(whole.t_stance, rel=2e-9)


def test_eq137_eq151_decompression_half_from_the_exact_bottom_reaches_the_exact_liftoff():
    """From the exact simulator's bottom state, the decompression half's liftoff state and time
    (measured: 1.4e-7 to 7.9e-6 relative, the 4-node quadrature floor of the slow landing)."""
    for td in TOUCHDOWNS:
        exact = slipmaps.stance("exact", VARIABLE, td)
        d = slipmaps.half_stance("iterative-decompression", VARIABLE, exact.bottom)
        assert d.ok, d.message
        assert d["end"] == pytest.approx(exact.liftoff, rel=2e-5)
        assert d["t_half"] == pytest.approx(exact.t_stance - exact.t_bottom, rel=2e-5)


def test_half_batch_rows_equal_scalar_calls_and_bad_rows_get_their_own_status():
    rows = np.array([TOUCHDOWNS[0], (1.0, 1.0, 0.3, -4.0), (1.0, -1.5, 2.0, -4.0)])
    res = slipmaps.half_stance_batch("iterative-compression", VARIABLE, rows, nodes="3", iterations=4)
    assert list(res["status"]) == [Status.OK, Status.TOUCHDOWN_NOT_COMPRESSING, Status.INVALID_INPUT]
    one = slipmaps.half_stance("iterative-compression", VARIABLE, rows[0], nodes="3", iterations=4)
    assert tuple(res["end"][0]) == one["end"] and res["passes"][0] == one["passes"] == 4
    with pytest.raises(ValueError, match="bottom state q_r"):  # a bottom leg longer than l0
        slipmaps.half_stance("iterative-decompression", VARIABLE, (1.2, 0.0, 0.0, -4.0))
    bottoms = np.array([one["end"], (0.9, 0.0, 1.7, -4.0)])  # the second leg is below horizontal
    res = slipmaps.half_stance_batch("iterative-decompression", VARIABLE, bottoms)
    assert list(res["status"]) == [Status.OK, Status.INVALID_INPUT]


def test_half_maps_are_listed_and_refuse_the_whole_stance_api():
    from slipmaps.runtime.api.index import halves as all_halves

    halves = {h.name: h for h in all_halves()}
    assert {n: (h.section, h.start, h.end) for n, h in halves.items()} == {
        "exact-compression": ("2.2", "touchdown", "bottom"),
        "exact-decompression": ("2.2", "bottom", "liftoff"),
        "iterative-compression": ("5.2.1", "touchdown", "bottom"),
        "iterative-decompression": ("5.2.2", "bottom", "liftoff"),
        "iterative-report-compression": ("5.2.1", "touchdown", "bottom"),
        "iterative-report-decompression": ("5.2.2", "bottom", "liftoff"),
    }
    with pytest.raises(ValueError, match="half-stance map"):
        slipmaps.stance("iterative-compression", VARIABLE, TOUCHDOWNS[0])
    with pytest.raises(ValueError, match="whole-stance map"):
        slipmaps.half_stance("iterative", VARIABLE, TOUCHDOWNS[0])
