"""The C99 swing-policy evaluation (derive/templates/c/swing.{h,c}.j2) against the numba one
(runtime/control/swing_tables.py) it ports: rendered as the C target renders it, compiled
warning-free alone (it needs no map), and on policies of ``geyer`` and ``iterative``
(slipmaps.swing_policy: the angle alone; the angle and a stiffness; tables with MAP_FAILED and
UNREACHABLE grounds, and an apex with no knot) at random times, apex heights and grounds: the same
slopes, values, touchdown times and angles, and the same ``where`` and ``knot``.

Measured (this file, 2 cores shared): every compared value bit-identical (max difference 0.0) on
every case; the test's bound is 1e-12 (relative, floor 1). ``SLIPMAPS_C_TIMING=1`` also times the
C evaluation from a C loop (printed with -s): measured on 64-knot policies, load 1.4 on 2 cores,
controls_at 50 ns for 3 controls (19 ns for one), touchdown 1.69 us (numba's touchdown_rows
1.82 us per row), touchdown and 3 controls 1.73 us.
"""

from __future__ import annotations

import ctypes
import os
import zlib

import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.control import swing_tables
from slipmaps.runtime.export import swing_c
from slipmaps.runtime.export.clib import compile_library

P = slipmaps.HUMAN_RUNNER
TOL = 1e-12
H, V, D = 1.3, 5.0, 0.3
#: The largest difference of each case (printed by the last test, with -s).
MEASURED: dict[str, float] = {}

HARNESS = r"""
#define _POSIX_C_SOURCE 199309L
#include <time.h>
#include "slipmaps_swing.h"

static double seconds(struct timespec a, struct timespec b)
{
    return (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
}

int harness_constants(int *c)
{
    c[0] = SLIPMAPS_SWING_IN_RANGE;
    c[1] = SLIPMAPS_SWING_ABOVE_RANGE;
    c[2] = SLIPMAPS_SWING_BELOW_RANGE;
    c[3] = SLIPMAPS_SWING_NO_POLICY;
    return 4;
}

double harness_edge(void) { return SLIPMAPS_SWING_EDGE; }

/* Seconds per slipmaps_swing_controls_at (n_controls controls) over the times x, reps times. */
double harness_time_controls(const double *t, int count, const double *Y, const double *M,
                             int n_controls, int stride, const double *x, int n, int reps,
                             double *sink)
{
    struct timespec t0, t1;
    double out[8], acc = 0.0;
    int i, k;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (k = 0; k < reps; k++)
        for (i = 0; i < n; i++) {
            slipmaps_swing_controls_at(t, count, Y, M, n_controls, stride, x[i], out);
            acc += out[n_controls - 1];
        }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    *sink = acc;
    return seconds(t0, t1) / ((double)reps * n);
}

/* Seconds per slipmaps_swing_touchdown (which = 0) or slipmaps_swing_step (which = 1) over the
 * (apex height, ground) pairs, reps times. */
double harness_time_touchdown(int which, double g, double q, const double *t, int count,
                              const double *Y, const double *M, int n_controls, int stride,
                              const double *h, const double *ground, int n, int reps, double *sink)
{
    struct timespec t0, t1;
    double out[8], td, angle, acc = 0.0;
    int i, k, knot;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (k = 0; k < reps; k++)
        for (i = 0; i < n; i++) {
            if (which == 0) {
                slipmaps_swing_touchdown(h[i], ground[i], g, q, t, Y, M, count, &td, &angle, &knot);
                acc += angle;
            } else {
                slipmaps_swing_step(h[i], ground[i], g, q, t, count, Y, M, n_controls, stride, &td,
                                    out, &knot);
                acc += out[n_controls - 1];
            }
        }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    *sink = acc;
    return seconds(t0, t1) / ((double)reps * n);
}
"""


@pytest.fixture(scope="module")
def lib(c_export, tmp_path_factory):
    """The exported swing evaluation (tests/conftest.py's ``c_export``: rendered by
    ``slipmaps generate --target c`` and compiled with the export's strict flags) built with the
    harness into a library."""
    own = tmp_path_factory.mktemp("c_swing")
    (own / "swing_harness.c").write_text(HARNESS)
    so = compile_library(
        [c_export / "slipmaps_swing.o", own / "swing_harness.c"],
        own / "libswing.so",
        extra=["-I", str(c_export)],
    )
    return swing_c.bind(ctypes.CDLL(str(so)))


#: name: (map, controls, target height, grounds, knots, apex height)
POLICIES = {
    "geyer angle": ("geyer", ("touchdown_angle",), None, (-D, D), 64, H),
    "geyer angle+k": ("geyer", ("touchdown_angle", "k"), H, (-D, D), 64, H),
    "iterative angle": ("iterative", ("touchdown_angle",), None, (-D, D), 64, H),
    "iterative angle+k_d": ("iterative", ("touchdown_angle", "k_d"), H, (-D, D), 64, H),
    # grounds up to 1.2 m: MAP_FAILED (no knot) and UNREACHABLE grounds
    "iterative angle+k_d failing": ("iterative", ("touchdown_angle", "k_d"), H, (-0.5, 1.2), 24, H),
    # a few knots: the ends' slopes and the short tables
    "iterative angle+k_d 3 knots": ("iterative", ("touchdown_angle", "k_d"), H, (-D, D), 3, H),
    "geyer angle 2 knots": ("geyer", ("touchdown_angle",), None, (-D, D), 2, H),
}
_CACHE: dict = {}


def policy(name):
    if name not in _CACHE:
        model, controls, tgt_h, grounds, n, h = POLICIES[name]
        _CACHE[name] = slipmaps.swing_policy(
            model, P, h, V, tgt_h, V, grounds=grounds, controls=controls, n=n
        )
    return _CACHE[name]


def _close(case, ref, got):
    """NaN where the other is NaN, the rest within TOL (relative, floor 1); records the largest."""
    ref, got = np.asarray(ref, dtype=float), np.asarray(got, dtype=float)
    np.testing.assert_array_equal(np.isnan(ref), np.isnan(got), err_msg=f"{case}: NaN places")
    ok = ~np.isnan(ref)
    diff = np.abs(ref[ok] - got[ok]) / np.maximum(1.0, np.abs(ref[ok]))
    worst = float(diff.max()) if diff.size else 0.0
    MEASURED[case] = max(MEASURED.get(case, 0.0), worst)
    assert worst <= TOL, f"{case}: max difference {worst:.3g}"


def _times(T, count, rng, n=4000):
    """Random times over the table and beyond both ends, the knots themselves, 0 and NaN."""
    t = T[:count]
    span = t[-1] - t[0] if count > 1 else 0.1
    x = rng.uniform(t[0] - 0.3 * span - 0.05, t[-1] + 0.3 * span + 0.05, n)
    near = t[rng.integers(0, count, 200)] * (1.0 + rng.uniform(-1e-12, 1e-12, 200))
    return np.concatenate([x, t, near, [0.0, -1.0, np.nan, np.inf]])


def _heights_grounds(tables, rng, n=3000):
    """Random apex heights near the policy's and grounds over and beyond its range, and grounds
    above the foot at the apex (NaN touchdown)."""
    g = tables.grounds[0]
    lo, hi = g.min(), g.max()
    h = H + rng.uniform(-0.15, 0.15, n)
    gr = rng.uniform(lo - 0.2 * (hi - lo), hi + 0.2 * (hi - lo), n)
    # the knots' own grounds from the policy's apex (touchdown at a knot, to round-off)
    h = np.concatenate([h, np.full(g.size, H), [H, H]])
    gr = np.concatenate([gr, g, [H, H + 1.0]])
    return h, gr


@pytest.mark.parametrize("name", list(POLICIES))
def test_c_slopes_are_the_numba_slopes(lib, name):
    tb = policy(name)._tables
    for c in swing_c.TABLE:
        M = swing_c.slopes_rows(lib, tb.T, tb.values[c], tb.counts)
        _close(f"{name} slopes {c}", tb.slopes[c], M)
        n = int(tb.counts[0])
        if n:
            _close(
                f"{name} slopes {c}",
                tb.slopes[c][0, :n],
                swing_c.slopes(lib, tb.T[0, :n], tb.values[c][0, :n]),
            )


@pytest.mark.parametrize("name", list(POLICIES))
def test_c_controls_are_the_numba_controls(lib, name):
    pol = policy(name)
    tb = pol._tables
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    x = _times(tb.T[0], int(tb.counts[0]), rng)
    ref = tb.controls_at(x)
    got = swing_c.controls_at(lib, tb, x)
    for c in swing_c.TABLE:
        _close(f"{name} controls_at", ref[c], got[c])
    # the one-policy form (slipmaps_swing_controls_at, the controls stacked)
    Y, M = swing_c.stacked(tb)
    out = (ctypes.c_double * 3)()
    for i in range(0, x.size, 37):
        lib.slipmaps_swing_controls_at(tb.T[0].ctypes.data, int(tb.counts[0]), Y.ctypes.data, M.ctypes.data,
                                       3, Y.shape[1], float(x[i]), out)  # fmt: skip
        _close(f"{name} controls_at", [ref[c][i] for c in swing_c.TABLE], list(out))


@pytest.mark.parametrize("name", list(POLICIES))
def test_c_touchdown_is_the_numba_touchdown(lib, name):
    pol = policy(name)
    tb = pol._tables
    rng = np.random.default_rng(zlib.crc32((name + " td").encode()))
    h, gr = _heights_grounds(tb, rng)
    A, MA = tb.values["touchdown_angle"], tb.slopes["touchdown_angle"]
    n = h.size
    t, a = np.empty(n), np.empty(n)
    where, knot = np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
    swing_tables.touchdown_rows(h, gr, tb.g_f, tb.q_r_td, tb.T, A, MA, tb.counts, t, a, where, knot)
    got = swing_c.touchdown_rows(lib, h, gr, tb.g_f, tb.q_r_td, tb.T, A, MA, tb.counts)
    _close(f"{name} touchdown", t, got["t"])
    _close(f"{name} touchdown", a, got["angle"])
    np.testing.assert_array_equal(got["where"], where)
    np.testing.assert_array_equal(got["knot"], knot)
    seen = set(where.tolist())
    assert {swing_tables.IN_RANGE, swing_tables.ABOVE_RANGE, swing_tables.BELOW_RANGE} <= seen, seen
    assert np.isnan(t).any()  # grounds above the foot at the apex
    # the whole step as the policy gives it (PolicyTables.touchdown) and slipmaps_swing_step
    ref = tb.touchdown(h, gr)
    for got in (swing_c.touchdown(lib, tb, h, gr), swing_c.step(lib, tb, h[:500], gr[:500])):
        m = got["t"].size
        for c in ("t", *swing_c.TABLE):
            _close(f"{name} touchdown", ref["t" if c == "t" else c][:m], got[c])
        np.testing.assert_array_equal(got["where"], where[:m])
        np.testing.assert_array_equal(got["knot"], knot[:m])


@pytest.mark.parametrize("name", ["geyer angle", "iterative angle+k_d", "iterative angle+k_d failing"])
def test_c_touchdown_at_the_end_knots(lib, name):
    """Grounds within round-off of the first and last knots' (the _EDGE branches: a root at the
    first knot in the table or above it; the held last angle in the table or below it)."""
    tb = policy(name)._tables
    n = int(tb.counts[0])
    T, A, MA = tb.T, tb.values["touchdown_angle"], tb.slopes["touchdown_angle"]
    rng = np.random.default_rng(zlib.crc32((name + " ends").encode()))
    g = np.concatenate(
        [
            H - 0.5 * tb.g_f * T[0, k] ** 2 - tb.q_r_td * np.cos(A[0, k]) + rng.uniform(-1e-12, 1e-12, 400)
            for k in (0, n - 1)
        ]
    )
    h = np.full(g.size, H)
    t, a = np.empty(g.size), np.empty(g.size)
    where, knot = np.empty(g.size, dtype=np.int64), np.empty(g.size, dtype=np.int64)
    swing_tables.touchdown_rows(h, g, tb.g_f, tb.q_r_td, T, A, MA, tb.counts, t, a, where, knot)
    got = swing_c.touchdown_rows(lib, h, g, tb.g_f, tb.q_r_td, T, A, MA, tb.counts)
    _close(f"{name} end knots", t, got["t"])
    _close(f"{name} end knots", a, got["angle"])
    np.testing.assert_array_equal(got["where"], where)
    np.testing.assert_array_equal(got["knot"], knot)
    inside = where == swing_tables.IN_RANGE
    assert (where == swing_tables.ABOVE_RANGE).any() and (inside & (t <= T[0, 0])).any()
    assert (inside & (knot == n - 2) & (t > T[0, n - 1])).any()  # the last knot, to round-off


def test_the_failing_policy_has_failed_and_unreachable_grounds():
    st = set(policy("iterative angle+k_d failing").status)
    assert {"MAP_FAILED", "UNREACHABLE", "REACHED"} <= st, st


def test_c_rows_of_synthetic_tables(lib):
    """Tables of many rows (0, 1, 2, 3 and more knots, NaN padded), one query per row; and one
    row for every query."""
    rng = np.random.default_rng(11)
    rows, width = 300, 9
    counts = rng.integers(0, width + 1, rows)
    counts[:4] = [0, 1, 2, 3]
    T = np.full((rows, width), np.nan)
    A = np.full((rows, width), np.nan)
    for r in range(rows):
        n = counts[r]
        T[r, :n] = np.sort(rng.uniform(0.1, 0.45, n)) + np.arange(n) * 1e-3
        A[r, :n] = 0.35 + 0.3 * (T[r, :n] - 0.25) + rng.normal(0, 0.02, n)
    M = swing_tables.empty_slopes(T)
    swing_tables.slopes_rows(T, A, counts, M)
    _close("synthetic slopes", M, swing_c.slopes_rows(lib, T, A, counts))
    x = rng.uniform(0.0, 0.6, rows)
    ref = np.empty(rows)
    swing_tables.evaluate_rows(T, A, M, counts, x, ref)
    _close("synthetic values", ref, swing_c.evaluate_rows(lib, T, A, M, counts, x))
    h, gr = rng.uniform(0.9, 1.4, rows), rng.uniform(-0.4, 0.4, rows)
    t, a = np.empty(rows), np.empty(rows)
    where, knot = np.empty(rows, dtype=np.int64), np.empty(rows, dtype=np.int64)
    swing_tables.touchdown_rows(h, gr, P.g_f, P.q_r_td, T, A, M, counts, t, a, where, knot)
    got = swing_c.touchdown_rows(lib, h, gr, P.g_f, P.q_r_td, T, A, M, counts)
    _close("synthetic touchdown", t, got["t"])
    _close("synthetic touchdown", a, got["angle"])
    np.testing.assert_array_equal(got["where"], where)
    np.testing.assert_array_equal(got["knot"], knot)
    assert where[0] == swing_tables.NO_POLICY and np.isnan(got["t"][0]) and np.isnan(got["angle"][0])
    # one row (a 3-knot table) for every query
    one = slice(3, 4)
    ref = np.empty(rows)
    swing_tables.evaluate_rows(T[one], A[one], M[one], counts[one], x, ref)
    _close("synthetic values", ref, swing_c.evaluate_rows(lib, T[one], A[one], M[one], counts[one], x))


def test_c_no_policy(lib):
    """An apex too low for any ground of the table: no knot (count 0), NO_POLICY and NaN."""
    tb = slipmaps.swing_policy("geyer", P, 0.3, V, None, V, grounds=(0.0, 0.2), n=4)._tables
    assert tb.counts[0] == 0
    got = swing_c.touchdown(lib, tb, [0.3, 1.0], [0.1, 0.0])
    ref = tb.touchdown([0.3, 1.0], [0.1, 0.0])
    assert got["where"].tolist() == [swing_tables.NO_POLICY] * 2
    for c in ("t", *swing_c.TABLE):
        _close("no policy", ref[c], got[c])
        assert np.isnan(got[c]).all()


def test_c_constants(lib):
    c = (ctypes.c_int * 4)()
    assert lib.harness_constants(c) == 4
    want = [swing_tables.IN_RANGE, swing_tables.ABOVE_RANGE, swing_tables.BELOW_RANGE, swing_tables.NO_POLICY]
    assert list(c) == want
    lib.harness_edge.restype = ctypes.c_double
    assert lib.harness_edge() == swing_tables._EDGE


@pytest.mark.skipif(
    not os.environ.get("SLIPMAPS_C_TIMING"), reason="SLIPMAPS_C_TIMING=1 times the C evaluation"
)
def test_c_timing(lib):
    """Nanoseconds per C evaluation from a C loop (the best of 5): controls_at (3 controls) at
    random times over the table, touchdown and step (touchdown and the 3 controls) at random
    grounds, on 64-knot policies."""
    with open("/proc/loadavg") as fh:
        print("\nload before:", fh.read().strip())
    vp, i, d = ctypes.c_void_p, ctypes.c_int, ctypes.c_double
    fc, ft = lib.harness_time_controls, lib.harness_time_touchdown
    fc.restype = ft.restype = d
    fc.argtypes = [vp, i, vp, vp, i, i, vp, i, i, vp]
    ft.argtypes = [i, d, d, vp, i, vp, vp, i, i, vp, vp, i, i, vp]
    sink = ctypes.c_double()
    for name in ("geyer angle", "iterative angle+k_d"):
        tb = policy(name)._tables
        rng = np.random.default_rng(5)
        Y, M = swing_c.stacked(tb)
        t, count = np.ascontiguousarray(tb.T[0]), int(tb.counts[0])
        x = rng.uniform(t[0], t[count - 1], 1000)
        h = np.full(1000, H)
        gr = rng.uniform(-D, D, 1000)
        table = (t.ctypes.data, count, Y.ctypes.data, M.ctypes.data)
        sk = ctypes.byref(sink)
        c = min(fc(*table, 3, Y.shape[1], x.ctypes.data, 1000, 200, sk) for _ in range(5))
        one = min(fc(*table, 1, Y.shape[1], x.ctypes.data, 1000, 200, sk) for _ in range(5))
        td = [
            min(
                ft(
                    which,
                    tb.g_f,
                    tb.q_r_td,
                    t.ctypes.data,
                    count,
                    Y.ctypes.data,
                    M.ctypes.data,
                    3,
                    Y.shape[1],
                    h.ctypes.data,
                    gr.ctypes.data,
                    1000,
                    20,
                    sk,
                )
                for _ in range(5)
            )  # fmt: skip
            for which in (0, 1)
        ]
        with open("/proc/loadavg") as fh:
            load = fh.read().split()[0]
        print(
            f"{name} ({count} knots): controls_at 3 controls {c * 1e9:.1f} ns, 1 control {one * 1e9:.1f} ns; "
            f"touchdown {td[0] * 1e9:.0f} ns, step (touchdown + 3 controls) {td[1] * 1e9:.0f} ns; load {load}"
        )


def test_report_measured():
    """The largest difference of every case (run with -s to see it)."""
    for case, worst in sorted(MEASURED.items()):
        print(f"{case}: {worst:.3g}")
