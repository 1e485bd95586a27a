"""The public API of the top-level package, generic over maps: SlipParams, maps(), stance,
stance_batch, apex_return, apex_return_batch, trajectory; one result family for exact and
approximate maps; errors that name the bad value."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
import slipmaps
from slipmaps import SlipParams, Status
from slipmaps.generated import maps_index

P = slipmaps.HUMAN_RUNNER
TD = (1.0, -1.5, 0.35, -4.5)
GENERATED = [row["name"] for row in maps_index.MAPS]


def test_slip_params_k_sets_both_stiffnesses():
    p = SlipParams(m=70.0, l0=0.9, k=18_000.0)
    assert (p.k_c, p.k_d, p.k) == (18_000.0, 18_000.0, 18_000.0)
    assert (p.q_r_td, p.q_r_lo) == (0.9, 0.9)
    q = SlipParams(m=70.0, l0=0.9, k_c=18_000.0, k_d=20_000.0)
    assert not q.constant_stiffness
    with pytest.raises(ValueError, match="k_c=18000.0"):
        q.k  # noqa: B018
    assert p.with_(k=10.0).k_d == 10.0


@pytest.mark.parametrize(
    ("kwargs", "needle"),
    [
        ({"k": 1.0, "k_c": 2.0}, "not both"),
        ({"m": -1.0}, "SlipParams.m"),
        ({"l0": math.nan}, "SlipParams.l0"),
        ({"q_r_lo": 1.5}, "rest length"),
        ({"g_s": "9.81"}, "real number"),
    ],
)
def test_slip_params_reject_bad_values(kwargs, needle):
    with pytest.raises(ValueError, match=needle):
        SlipParams(**kwargs)


def test_maps_index_lists_generated_maps_then_exact():
    rows = slipmaps.maps()
    assert [m.name for m in rows] == [*GENERATED, "exact"]
    for m in rows:
        assert m.title and m.section and m.equations
    assert "constant_stiffness" in next(m for m in rows if m.name == "geyer").requires


def test_exact_map_defaults_are_the_simulators():
    exact = next(m for m in slipmaps.maps() if m.name == "exact")
    from slipmaps.runtime.exact import reference as simulate

    assert exact.option("rtol").default == simulate.DEFAULT_RTOL
    assert exact.option("atol").default == simulate.DEFAULT_ATOL


def test_importing_the_derivations_does_not_need_the_runtime():
    """`slipmaps generate` must work on a stale or half-generated tree: importing slipmaps.derive
    loads nothing from slipmaps.runtime or the generated kernels."""
    code = "import sys, slipmaps.derive.maps; print([m for m in sys.modules if m.startswith('slipmaps.')])"
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert "runtime" not in out and "slipmaps.generated" not in out


@pytest.mark.parametrize("name", [*GENERATED, "exact"])
def test_one_result_family_for_every_map(name):
    st = slipmaps.stance(name, P, TD)
    assert st.ok, st.message
    assert set(slipmaps.stance("geyer", P, TD).values) <= set(st.values)
    assert len(st.liftoff) == 4 and st.liftoff[0] == pytest.approx(P.q_r_lo, rel=1e-12)
    assert st["t_stance"] == st.t_stance > st.t_bottom > 0
    ap = slipmaps.apex_return(name, P, 1.0, 5.0, 0.35)
    assert ap.ok and {"next_apex_height", "next_apex_speed", "t_descent", "t_stance", "t_ascent"} <= set(
        ap.values
    )
    if next(m for m in slipmaps.maps() if m.name == name).as_printed:
        return  # reproduces the report's formulas to measure them (iterative-report: 1.035 m)
    # exact: 0.917730 m; measured errors of the maps: -1.5 mm (type 0) to +0.84 mm (type 5)
    assert ap.next_apex_height == pytest.approx(0.917730, abs=0.003)


def test_stance_batch_rows_equal_scalar_calls_and_bad_rows_get_their_own_status():
    rows = np.array([TD, (1.0, -2.0, 0.30, -5.0), (math.nan, -2.0, 0.3, -5.0), (1.0, -2.0, 2.0, -5.0)])
    res = slipmaps.stance_batch("gravity-type2", P, rows)
    assert res.shape == (4,) and list(res["status"][2:]) == [Status.INVALID_INPUT] * 2
    for i in range(2):
        one = slipmaps.stance("gravity-type2", P, rows[i])
        for key, value in one.values.items():
            assert res[key][i] == value, key
    assert res["liftoff"].shape == (4, 4) and np.isnan(res["liftoff"][2]).all()
    assert res.counts() == {"OK": 2, "INVALID_INPUT": 2}


@pytest.mark.parametrize("name", GENERATED)
@pytest.mark.parametrize("role", ["stance", "stance_jacobian"])
def test_a_record_field_that_is_also_an_input_is_read_from_the_input(name, role):
    """The stance's parameter record holds the touchdown leg length q_r_td, which is also its
    first input: the batch driver fills the record once for every row (calls.layout_rows), so the
    role kernel must read q_r_td from x. The record's copy NaN: the same outputs, bit for bit."""
    from slipmaps.runtime.api.batch import run_rows
    from slipmaps.runtime.api.calls import Call, kernel_functions

    call = Call.of(name, P, {})
    spec = call.spec(role)
    shadowed = [j for j, f in enumerate(spec.p) if f in spec.x]
    assert [spec.p[j] for j in shadowed] == ["q_r_td"], spec.p
    rng = np.random.default_rng(7)
    n = 64
    X = np.column_stack(
        [
            rng.uniform(0.9, 1.0, n),
            rng.uniform(-2.0, -1.0, n),
            rng.uniform(0.25, 0.4, n),
            rng.uniform(-5.5, -3.5, n),
        ]
    )
    rows = kernel_functions(spec)[1]
    outs = []
    for fill in (None, math.nan):
        record = call.record(spec).copy()[None, :]
        if fill is not None:
            record[0, shadowed] = fill
        out, status = np.empty((n, spec.width)), np.empty(n, dtype=np.int64)
        run_rows(rows, X, record, out, status)
        outs.append((out, status))
    (a, sa), (b, sb) = outs
    assert (sa == int(Status.OK)).sum() >= n // 2, np.unique(sa, return_counts=True)
    np.testing.assert_array_equal(sa, sb)
    np.testing.assert_array_equal(a, b)


def test_apex_return_batch_broadcasts_and_keeps_the_shape():
    speeds = np.array([3.0, 4.0, 5.0])
    angles = np.array([[0.30], [0.35]])
    res = slipmaps.apex_return_batch("geyer", P, 1.0, speeds, angles)
    assert (
        res.shape == (2, 3) and res["next_apex_height"].shape == (2, 3) and res["liftoff"].shape == (2, 3, 4)
    )
    for i, a in enumerate(angles[:, 0]):
        for j, v in enumerate(speeds):
            one = slipmaps.apex_return("geyer", P, 1.0, v, a)
            assert res["next_apex_speed"][i, j] == one.next_apex_speed and res["status"][i, j] == one.status


def test_exact_batch_equals_scalar_and_marks_invalid_rows():
    rows = np.array([TD, (1.0, 1.0, 0.3, -5.0), (2.0, -1.0, 0.3, -5.0)])
    res = slipmaps.stance_batch("exact", P, rows)
    assert list(res["status"]) == [Status.OK, Status.TOUCHDOWN_NOT_COMPRESSING, Status.INVALID_INPUT]
    assert res["t_stance"][0] == slipmaps.stance("exact", P, TD).t_stance


def test_options_are_validated_with_the_valid_values_named():
    with pytest.raises(ValueError, match="its options: reading, samples"):
        slipmaps.stance("gravity-type2", P, TD, sample=3)
    with pytest.raises(ValueError, match="'mean', 'report'"):
        slipmaps.stance("gravity-type2", P, TD, reading="literal")
    with pytest.raises(ValueError, match=r"\[2, 3\]"):
        slipmaps.stance("gravity-type2", P, TD, samples=4)
    with pytest.raises(ValueError, match="unknown map 'geyr'"):
        slipmaps.stance("geyr", P, TD)
    one = slipmaps.stance("gravity-type2", P, TD, reading="report", iterations=1, tol=0.0)
    assert one.ok and one.passes == 1.0 and one.inputs["options"]["reading"] == "report"


def test_constant_stiffness_maps_name_the_alternatives():
    vs = SlipParams(k_c=20_000.0, k_d=25_000.0)
    with pytest.raises(ValueError, match="constant leg stiffness.*accept k_c != k_d: .*exact"):
        slipmaps.apex_return("geyer", vs, 1.0, 5.0, 0.35)
    assert slipmaps.apex_return("exact", vs, 1.0, 5.0, 0.35).ok


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda: slipmaps.stance("geyer", P, (1.2, -1.0, 0.3, -4.0)), "q_r"),
        (lambda: slipmaps.stance("geyer", P, (1.0, -1.0, 0.3)), "4 numbers"),
        (lambda: slipmaps.apex_return("geyer", P, -1.0, 5.0, 0.3), "apex_height"),
        (lambda: slipmaps.apex_return("geyer", P, 1.0, math.inf, 0.3), "apex_speed"),
        (lambda: slipmaps.apex_return("geyer", P, 1.0, 5.0, 1.6), "touchdown_angle"),
        (lambda: slipmaps.stance_batch("geyer", P, np.zeros((3, 3))), "shape"),
        (lambda: slipmaps.stance("geyer", "not params", TD), "SlipParams"),
    ],
)
def test_scalar_calls_name_the_bad_argument(call, needle):
    with pytest.raises((ValueError, TypeError), match=needle):
        call()


WITH_TRAJECTORY = [m.name for m in slipmaps.maps() if m.has_trajectory]
WITHOUT_TRAJECTORY = [m for m in GENERATED if m not in WITH_TRAJECTORY]


def test_both_kinds_of_map_are_tested():
    """The two tests below run over filtered lists: neither may be empty (an empty one runs nothing)."""
    assert WITH_TRAJECTORY and WITHOUT_TRAJECTORY


@pytest.mark.parametrize("name", WITHOUT_TRAJECTORY)
def test_maps_without_trajectory_say_so(name):
    with pytest.raises(ValueError, match="no trajectory"):
        slipmaps.trajectory(name, P, TD)


@pytest.mark.parametrize("name", WITH_TRAJECTORY)
def test_trajectory_ends_at_the_liftoff_state(name):
    res = slipmaps.stance(name, P, TD)
    t, states, status = slipmaps.trajectory(name, P, TD)
    assert status == Status.OK and t[0] == 0.0 and t[-1] == res.t_stance
    # the liftoff leg length and angle are the trajectory's at t_stance (measured: 3.3e-16);
    # q_rd and q_thd at liftoff may be corrected separately (the gravity maps' energy-based q_rd)
    assert states[-1, 0] == pytest.approx(res.liftoff_q_r, abs=1e-12)
    assert states[-1, 2] == pytest.approx(res.liftoff_q_th, abs=1e-12)
    assert states[0] == pytest.approx(np.array(TD), abs=1e-12)  # measured: 8.9e-16


def test_exact_trajectory_at_any_times_is_the_reference_dense_output():
    """The exact map samples its stance at any times (the compiled simulator's state_at kernel);
    the solve_ivp reference (method="scipy") evaluates its dense output there: they agree to the
    integration tolerance (measured 7.9e-11 over the default 200 samples)."""
    t, states, status = slipmaps.trajectory("exact", P, TD)
    assert status == Status.OK and states.shape == (t.size, 4) == (200, 4)
    t_ref, ref, status_ref = slipmaps.trajectory("exact", P, TD, t=t, method="scipy")
    assert status_ref == Status.OK and np.array_equal(t_ref, t)
    assert np.max(np.abs(states - ref)) < 1e-9
    some, _, _ = slipmaps.trajectory("exact", P, TD, t=[0.0, 0.1])
    assert some.tolist() == [0.0, 0.1]


def test_readme_python_example_runs():
    """The Python API example (moved from the README to docs/getting_started.md), executed as written."""
    from documents import section_block

    block = section_block("docs/getting_started.md", "Python API")
    namespace: dict = {}
    exec(compile(block, "docs/getting_started.md", "exec"), namespace)  # noqa: S102 - the project's own docs
    assert namespace["step"].ok and namespace["st"].ok
    assert namespace["res"]["next_apex_height"].shape == (300, 400)


_APEX_FUNCTIONS = ("apex_return", "apex_return_batch", "apex_return_jacobian", "apex_return_jacobian_batch")


@pytest.mark.parametrize("fname", _APEX_FUNCTIONS)
def test_apex_signatures_come_from_the_inputs_table(fname):
    """The public apex-return functions take the inputs table's rows (derive/params.py): those
    without a default positionally after name and params, in order, those with one as keywords
    with it; wrong calls raise TypeError like a Python signature."""
    import inspect

    from slipmaps.derive.params import APEX_INPUTS

    func = getattr(slipmaps, fname)
    params = list(inspect.signature(func).parameters.values())[2:]
    table = [(r["name"], r.get("default", inspect.Parameter.empty)) for r in APEX_INPUTS]
    assert [(p.name, p.default) for p in params[: len(table)]] == table
    kinds = [p.kind for p in params[: len(table)]]
    assert kinds == [
        inspect.Parameter.KEYWORD_ONLY if "default" in r else inspect.Parameter.POSITIONAL_OR_KEYWORD
        for r in APEX_INPUTS
    ]
    p = slipmaps.HUMAN_RUNNER
    with pytest.raises(TypeError, match="missing required argument: 'touchdown_angle'"):
        func("geyer", p, 1.0, 5.0)
    with pytest.raises(TypeError, match="positional arguments"):
        func("geyer", p, 1.0, 5.0, 0.35, 0.0)
    with pytest.raises(TypeError, match="multiple values for argument 'apex_speed'"):
        func("geyer", p, 1.0, 5.0, 0.35, apex_speed=4.0)


def test_apex_inputs_by_position_and_by_name_agree():
    p = slipmaps.HUMAN_RUNNER
    a = slipmaps.apex_return("geyer", p, 1.0, 5.0, 0.35, ground=0.02)
    b = slipmaps.apex_return("geyer", p, touchdown_angle=0.35, apex_height=1.0, apex_speed=5.0, ground=0.02)
    assert a.ok and a.values == b.values
    c = slipmaps.apex_return("geyer", p, 1.0, 5.0, 0.35)
    assert c.inputs["ground"] == 0.0 and c.values != a.values


def test_status_prints_its_name_and_formats_its_code_on_request():
    """``print(result.status)`` shows the name (as PlanStatus does); a numeric format spec and JSON
    give the code."""
    import json

    assert str(Status.FALL) == "FALL" and f"{Status.OK}" == "OK" and f"{Status.OK:>4}" == "  OK"
    assert f"{Status.FALL:d}" == str(int(Status.FALL)) and json.dumps(Status.FALL) == str(int(Status.FALL))
    res = slipmaps.apex_return("geyer", slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35)
    assert str(res.status) == "OK"


def test_jacobian_batch_counts_rows_per_status_like_batch_result():
    jb = slipmaps.apex_return_jacobian_batch("geyer", slipmaps.HUMAN_RUNNER, [1.0, 1.0, 0.1], 5.0, 0.35)
    counts = jb.counts()
    assert counts == jb.result.counts() and sum(counts.values()) == 3
    assert counts["OK"] == 2 and len(counts) == 2


def test_deadbeat_picks_the_controls_a_map_has():
    """Without ``controls`` a constant-stiffness map is steered by the angle alone (it has no k_d),
    a map with k_c and k_d by the angle and k_d."""
    from slipmaps.runtime.control.deadbeat import Deadbeat

    P = slipmaps.HUMAN_RUNNER
    res = slipmaps.deadbeat("geyer", P, 1.0, 5.0, None, 5.0)
    assert res.status == "REACHED" and abs(res.next_apex_speed - 5.0) < 1e-6
    assert Deadbeat("geyer", P).controls == ("touchdown_angle",)
    assert Deadbeat("iterative", P).controls == ("touchdown_angle", "k_d")


def test_an_unreachable_step_names_the_touchdown_geometry_when_it_binds():
    """From a 0.9 m apex no angle below acos(0.9) touches down; a target that needs a steeper leg
    ends there, and the message says so (not an energy range suggesting it could be reached)."""
    P = slipmaps.HUMAN_RUNNER
    res = slipmaps.deadbeat("iterative", P, 0.9, 5.0, 1.2, 5.0)
    assert res.status == "UNREACHABLE" and res.touchdown_limit == pytest.approx(math.acos(0.9 / P.q_r_td))
    assert "touchdown geometry binds" in res.message and f"{res.touchdown_limit:.6g} rad" in res.message
    other = slipmaps.deadbeat("iterative", P, 0.9, 5.0, 2.0, 5.0)  # k_d's bound binds there instead
    assert other.status == "UNREACHABLE" and "geometry" not in other.message and "k_d at its" in other.message


# --- the touchdown state of a scalar stance: any container of 4 real numbers, checked the same way --
STATE = (0.98, -1.5, 0.35, -4.5)


@pytest.mark.parametrize(
    "given",
    [STATE, list(STATE), np.array(STATE), tuple(np.float64(v) for v in STATE), (1, -1.5, 0.35, -4.5)],
    ids=["tuple", "list", "array", "numpy-scalars", "an-int"],
)
def test_stance_takes_the_touchdown_in_any_container_of_four_numbers(given):
    expected = slipmaps.stance("geyer", slipmaps.HUMAN_RUNNER, tuple(float(v) for v in given))
    got = slipmaps.stance("geyer", slipmaps.HUMAN_RUNNER, given)
    assert got.status == Status.OK and got.values == expected.values


@pytest.mark.parametrize(
    ("given", "error", "says"),
    [
        ((0.98, math.nan, 0.35, -4.5), ValueError, "touchdown q_rd must be finite, got nan"),
        ((0.98, -1.5, math.inf, -4.5), ValueError, "touchdown q_th must be finite, got inf"),
        ((1.2, -1.5, 0.35, -4.5), ValueError, "touchdown q_r must lie in (0, l0=1.0], got 1.2"),
        ((0.98, -1.5, 1.6, -4.5), ValueError, "touchdown q_th must lie in (-pi/2, pi/2)"),
        ((0.98, -1.5, True, -4.5), TypeError, "touchdown q_th must be a real number, got bool True"),
        ((0.98, -1.5, 0.35), ValueError, "touchdown must be 4 numbers"),
        ("0.98", TypeError, "touchdown must be 4 numbers"),
    ],
)
def test_a_bad_touchdown_is_refused_naming_the_value(given, error, says):
    with pytest.raises(error) as info:
        slipmaps.stance("geyer", slipmaps.HUMAN_RUNNER, given)
    assert says in str(info.value)


@pytest.mark.parametrize("n", [0, 1, 8, 9, 17, 200, 1001])
@pytest.mark.parametrize("cost", [None, 0.0, 1.0])
def test_run_blocks_runs_every_row_once_whether_or_not_a_row_cost_is_known(monkeypatch, n, cost):
    """batch.run_blocks: the blocks cover rows 0..n once each, in order within a block, whether the
    cost of a row is measured on the first PROBE rows (cost None), known to be small (0: one
    thread) or known to be large (1 s: every thread, no probe, a row per block: a block is bounded
    in time, batch.BLOCK_SECONDS)."""
    import threading

    from slipmaps.runtime.api import batch

    monkeypatch.setattr(batch, "_threads", lambda: 3)
    key = object()
    if cost is not None:
        monkeypatch.setitem(batch._COST, key, cost)
    seen, lock = [], threading.Lock()

    def block(lo, hi):
        with lock:
            seen.append((lo, hi))

    batch.run_blocks(block, n, key)
    rows = sorted(i for lo, hi in seen for i in range(lo, hi))
    assert rows == list(range(n))
    if cost == 1.0 and n > batch.PROBE:
        assert (0, 1) in seen  # no probe; a row per block at first
    if cost is None and n > batch.PROBE:
        assert (0, batch.PROBE) in seen and key in batch._COST  # probed and remembered
        batch._COST.pop(key)


def test_run_blocks_does_not_remember_a_row_cost_measured_while_the_kernel_compiled():
    """A kernel's first rows in a process compile it (seconds): that time is not the cost of a row,
    so run_blocks times the next batch's first rows again instead of remembering it."""
    from slipmaps.runtime.api import batch

    class Kernel:  # a dispatcher's signatures: one more after a compilation
        signatures: list = []

    key = Kernel()

    def block(lo, hi):
        if not key.signatures:
            key.signatures = ["compiled"]

    batch.run_blocks(block, 100, key)
    assert key not in batch._COST
    batch.run_blocks(block, 100, key)
    assert key in batch._COST
    batch._COST.pop(key)


def test_support_row_borrows_a_row_of_a_contiguous_or_strided_array():
    """generated/support.py's ``row(A, i)``: row ``i`` of ``A`` (C-contiguous or strided) as a 1-D
    array on the same memory: what it reads is ``A[i]``, what it writes lands in ``A``."""
    from numba import njit
    from slipmaps.generated import support

    @njit
    def double_row(A, i):  # row is an intrinsic: callable from compiled code only
        r = support.row(A, i)
        for j in range(r.shape[0]):
            r[j] *= 2.0
        return r.shape[0]

    base = np.arange(24.0).reshape(4, 6)
    for A in (base.copy(), np.asfortranarray(base), base.copy()[:, ::2], base.copy()[::-1]):
        want = A.copy()
        want[2] *= 2.0
        assert double_row(A, 2) == A.shape[1]
        assert np.array_equal(A, want), A


def test_support_load_and_store_are_subscripts_compiled_and_in_python():
    """generated/support.py's ``load(a, i, ...)`` and ``store(a, values)``: what the kernels read
    and write at constant positions. Compiled, on a contiguous or a strided row, they read and
    write exactly the subscripts; in Python (a kernel's ``.py_func``) the same; ``load`` refuses
    positions that are not constants (the lowering always writes literals)."""
    from numba import njit
    from numba.core.errors import TypingError
    from slipmaps.generated import support

    @njit
    def swap_ends(a, b):
        (first, third, last) = support.load(a, 0, 2, 5)
        support.store(b, (last, third, first, 7))  # an integer stored as a float
        return first + last

    @njit
    def at(a, i):
        return support.load(a, i)

    base = np.arange(12.0)
    for a, b in ((base[:6].copy(), np.zeros(6)), (base[::2], np.zeros(12)[1::3])):
        for run in (swap_ends, swap_ends.py_func):
            out = b.copy()
            assert run(a, out) == a[0] + a[5]
            assert np.array_equal(out[:4], [a[5], a[2], a[0], 7.0]) and not out[4:].any(), out
    with pytest.raises(TypingError):
        at(base, 1)


def test_support_node_arrays_are_disjoint_rows_of_the_stack():
    """``node_arrays(stack(n * w), n, w)``: n arrays of w float64 each, one after the other on the
    kernel's stack (a kernel's node arrays): writing one leaves the others as they were."""
    from numba import njit
    from slipmaps.generated import support

    @njit
    def fill():
        (a, b, c) = support.node_arrays(support.stack(12), 3, 4)
        for j in range(4):
            a[j], b[j], c[j] = j, 10.0 + j, 20.0 + j
        a[0] = -1.0
        return a.shape[0], b[0], c[3], a[0] + a[1]

    assert fill() == (4, 10.0, 23.0, 0.0)


def test_batch_rows_of_strided_inputs_equal_contiguous_ones():
    """A role kernel's batch form borrows its rows (support.row) from whatever layout it is given:
    a Fortran-ordered ``X`` and a strided ``OUT`` give the rows of contiguous arrays."""
    from slipmaps.runtime.api.calls import Call, kernel_functions

    call = Call.of("geyer", slipmaps.HUMAN_RUNNER, {})
    spec = call.spec("apex_return")
    rows = kernel_functions(spec)[1]
    rng = np.random.default_rng(3)
    X = np.zeros((50, len(spec.x)))
    for name, (lo, hi) in {"b_y_apex": (1.0, 1.1), "b_xd_apex": (3, 7), "q_th_td": (0.3, 0.5)}.items():
        X[:, spec.x.index(name)] = rng.uniform(lo, hi, 50)
    P = call.record(spec, rows=True)
    out, status = np.empty((50, spec.width)), np.empty(50, dtype=np.int64)
    rows(X, P, out, status)
    wide, strided_status = np.full((50, 2 * spec.width), -1.0), np.empty(50, dtype=np.int64)
    rows(np.asfortranarray(X), np.asfortranarray(P), wide[:, ::2], strided_status)
    assert (status == 0).sum() > 40 and np.array_equal(status, strided_status)
    assert np.array_equal(out, wide[:, ::2], equal_nan=True) and (wide[:, 1::2] == -1.0).all()


def test_into_rows_inlines_a_role_kernel_into_its_own_batch_form_only():
    """generated/support.py's ``into_rows``, numba's inline cost model of the role kernels of a map
    that opts in (MapSpec.inline): yes for ``<kernel>_rows``, no for any other caller; geyer opts in."""
    from types import SimpleNamespace

    from slipmaps.generated import geyer, support

    def ir(name):
        return SimpleNamespace(func_id=SimpleNamespace(func_name=name))

    assert support.into_rows(None, ir("geyer_apex_return_rows"), ir("geyer_apex_return"))
    assert not support.into_rows(None, ir("geyer_apex_return_jacobian"), ir("geyer_apex_return"))
    assert not support.into_rows(None, ir("rows"), ir("geyer_apex_return"))
    assert geyer.geyer_apex_return.targetoptions["inline"] is support.into_rows


def test_layout_rows_takes_the_record_flat_or_as_its_batch_view():
    """``layout_rows`` hands the batch form a (1, k) ``P`` whether it is given the parameter record
    or its (1, k) view (``Call.record(spec, rows=True)``, made once per call)."""
    from slipmaps.runtime.api.calls import Call, layout_rows

    call = Call.of("geyer", slipmaps.HUMAN_RUNNER, {})
    spec = call.spec("apex_return")
    rows = {"b_y_apex": np.ones(3), "b_xd_apex": np.full(3, 5.0), "q_th_td": np.full(3, 0.35)}
    inputs = {"ground": 0.0, "retraction_rate": 0.0}
    flat = layout_rows(spec, call.record(spec), rows, inputs, 3)[1]
    view = layout_rows(spec, call.record(spec, rows=True), rows, inputs, 3)[1]
    assert flat.shape == view.shape == (1, len(spec.p)) and np.array_equal(flat, view)


@pytest.mark.parametrize("name", GENERATED)
def test_a_batch_of_one_row_is_that_row_of_a_longer_batch_bit_for_bit(name):
    """A batch of one row runs the row kernel as a scalar call does (calls.KernelBackend.rows), a
    longer one the kernel's batch form: the same values, derivatives and statuses, a failing row
    (a leg angle past the horizontal) included."""
    h, v = np.array([1.05, 1.0, 1.0]), np.array([5.0, 4.0, 4.0])
    a = np.array([0.35, 0.30, 1.6])
    tds = np.array([TD, (1.0, -2.0, 0.30, -5.0), (1.0, -2.0, 2.0, -5.0)])
    batches = [
        (slipmaps.apex_return_batch, (h, v, a)),
        (slipmaps.apex_return_jacobian_batch, (h, v, a)),
        (slipmaps.stance_batch, (tds,)),
        (slipmaps.stance_jacobian_batch, (tds,)),
    ]
    statuses = set()
    for batch, args in batches:
        many = batch(name, P, *args)
        for i in range(3):
            one = batch(name, P, *(x[i : i + 1] for x in args))
            assert one.status[0] == many.status[i], (batch.__name__, i)
            statuses.add(int(one.status[0]))
            got = one.matrix if hasattr(one, "matrix") else np.column_stack([one[k] for k in one.names])
            want = (
                many.matrix[i : i + 1]
                if hasattr(many, "matrix")
                else np.column_stack([many[k][i : i + 1] for k in many.names])
            )
            np.testing.assert_array_equal(got, want, err_msg=f"{batch.__name__} row {i}")
    assert int(Status.OK) in statuses and len(statuses) > 1  # OK rows and a failing one compared
