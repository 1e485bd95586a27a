"""The C99 deadbeat solver (derive/templates/c/deadbeat.{h,c}.j2) against the numba one
(runtime/control/compiled.py) it ports: rendered, compiled warning-free, and on random rows of
``geyer`` and ``iterative`` (the angle alone, the angle and a stiffness; REACHED, UNREACHABLE and
MAP_FAILED rows) the same statuses and counts, and the same controls, residuals and outputs.

The maps are the exported C maps (``slipmaps generate --target c``, tests/conftest.py's
``c_export``), which agree with the numba kernels to the bit (tests/test_c_export.py).

Measured (this file, 2 cores shared): every compared quantity bit-identical (max difference 0.0)
on every case; the test's bound is 1e-12 (relative with a floor of 1, absolute on the scaled
residual). ``SLIPMAPS_C_TIMING=1`` also times the C solve from a C loop (printed with -s).
"""

from __future__ import annotations

import ctypes
import math
import os
import zlib

import numpy as np
import pytest
import slipmaps
from slipmaps.generated.status import Status
from slipmaps.runtime.control import compiled
from slipmaps.runtime.control.bottom import BottomDeadbeat
from slipmaps.runtime.control.deadbeat import CONTROLS, Deadbeat, default_angle
from slipmaps.runtime.export import deadbeat_c
from slipmaps.runtime.export.clib import compile_library

P = slipmaps.HUMAN_RUNNER
TOL = 1e-12
HEAD = compiled.HEAD_AT
#: The largest difference of each case (printed by the last test, with -s).
MEASURED: dict[str, object] = {}

# A harness beside the solver: the structs' layouts (checked against the ctypes mirrors) and a C
# timing loop.
HARNESS = r"""
#define _POSIX_C_SOURCE 199309L
#include <stddef.h>
#include <time.h>
#include "slipmaps_deadbeat.h"

#define S_FIELDS(X) X(n_controls) X(in_p) X(pos) X(col) X(lo) X(hi) X(scale) X(targeted) \
    X(weight) X(tol) X(n_out) X(n_wrt) X(fd_step) X(out_height) X(out_speed) X(kd_in_p) \
    X(kd_pos) X(kd_lo) X(kd_hi) X(mass) X(g_f) X(max_evaluations) X(broyden) X(scan)
#define W_FIELDS(X) X(x) X(p) X(target) X(d) X(v) X(e) X(u0) X(z) X(zlo) X(zhi) X(G) X(zb) \
    X(Gb) X(rf) X(J) X(r) X(rt) X(F) X(delta) X(zt) X(free_) X(rows) X(cols) X(A) X(b) X(zs) \
    X(rs) X(ri) X(rg) X(stall)

size_t harness_settings_layout(size_t *at)
{
    size_t n = 0;
#define S_AT(f) at[n++] = offsetof(slipmaps_deadbeat_settings, f);
    S_FIELDS(S_AT)
    at[n] = sizeof(slipmaps_deadbeat_settings);
    return n;
}

size_t harness_work_layout(size_t *at)
{
    size_t n = 0;
#define W_AT(f) at[n++] = offsetof(slipmaps_deadbeat_work, f);
    W_FIELDS(W_AT)
    at[n] = sizeof(slipmaps_deadbeat_work);
    return n;
}

int harness_limits(int *lim)
{
    lim[0] = SLIPMAPS_MAX_X;
    lim[1] = SLIPMAPS_MAX_P;
    lim[2] = SLIPMAPS_MAX_OUT;
    lim[3] = SLIPMAPS_N_HEAD;
    lim[4] = SLIPMAPS_REACHED;
    lim[5] = SLIPMAPS_UNREACHABLE;
    lim[6] = SLIPMAPS_MAP_FAILED;
    return 7;
}

/* Seconds per solve: every row solved reps times, one work space. */
double harness_time(slipmaps_role_fn apex, slipmaps_role_fn jac, const double *X, int n, int nx,
                    const double *P, int p_rows, int np, const double *T,
                    const slipmaps_deadbeat_settings *s, double *OUT, int reps)
{
    slipmaps_deadbeat_work w;
    struct timespec t0, t1;
    int k;
    slipmaps_deadbeat_solve_rows(apex, jac, X, n, nx, P, p_rows, np, T, s, &w, OUT);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (k = 0; k < reps; k++)
        slipmaps_deadbeat_solve_rows(apex, jac, X, n, nx, P, p_rows, np, T, s, &w, OUT);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    return ((double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec)) / ((double)reps * n);
}

/* Seconds per call of a map kernel. */
double harness_time_map(slipmaps_role_fn f, const double *x, const double *p, double *out, int reps)
{
    struct timespec t0, t1;
    int k, code = 0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (k = 0; k < reps; k++)
        code += f(x, p, out);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if (code != 0)
        return -1.0;
    return ((double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec)) / reps;
}
"""


@pytest.fixture(scope="module")
def lib(c_export, tmp_path_factory):
    """The exported maps and solver (tests/conftest.py's ``c_export``) with the harness."""
    own = tmp_path_factory.mktemp("c_deadbeat")
    (own / "harness.c").write_text(HARNESS)
    so = own / "libdeadbeat.so"
    objects = [c_export / "slipmaps.o", c_export / "slipmaps_deadbeat.o"]
    compile_library([*objects, own / "harness.c"], so, extra=["-I", str(c_export)])
    lib = deadbeat_c.bind(ctypes.CDLL(str(so)))
    lib.harness_time.restype = ctypes.c_double
    _LIB["lib"] = lib
    return lib


#: The library the fixture built (the maps' vector forms are looked up in it).
_LIB: dict = {}


def map_pointers(apex, jac=None) -> tuple[int, int | None]:
    """(apex, jac) as C function pointers for the C solver, from the index's kernel specs: the
    exported C maps' vector forms ``slipmaps_<kernel>_v``."""

    def address(spec) -> int:
        return ctypes.cast(getattr(_LIB["lib"], f"slipmaps_{spec.name}_v"), ctypes.c_void_p).value

    return address(apex), None if jac is None else address(jac)


def _controller(name, controls, **options):
    ctl = Deadbeat(name, P, controls=controls, **options)
    ptrs = map_pointers(ctl.call.spec("apex_return"), ctl.call.spec("apex_return_jacobian"))
    return ctl, ptrs


def _rows(ctl, n, seed, tgt, *, far=0.0, low=0, heights=(0.85, 1.3)):
    """n random rows (X, P, T) as Deadbeat.plan_batch builds them: apex ``heights`` [m], 3-7 m/s,
    the target near (``far`` m/s beyond) it; ``low`` rows with an apex too low for any touchdown."""
    rng = np.random.default_rng(seed)
    h = rng.uniform(*heights, n)
    v = rng.uniform(3.0, 7.0, n)
    h[:low] = 0.1
    H = h + rng.uniform(-0.1, 0.1, n)
    V = v + rng.uniform(-0.4, 0.4, n) + far * rng.choice([-1.0, 1.0], n)
    angle = default_angle(P, v) + rng.uniform(-0.05, 0.05, n)
    cols = {"apex_height": h, "apex_speed": v, "touchdown_angle": angle, "ground": rng.uniform(-0.1, 0.1, n)}
    X = ctl._inputs(cols, n)
    Pr = ctl._record_clipped()[None, :]
    T = np.stack([H if tgt[0] else 0.0 * H, V if tgt[1] else 0.0 * V], axis=1)
    return X, Pr, np.ascontiguousarray(T)


def _compare(case, ref, out, nc):
    """Statuses and counts identical; the rest within TOL (relative, floor 1; the residual
    absolute); NaN where the other is NaN. Records the largest difference."""
    for name in ("plan_status", "map_status", "jacobians", "evaluations", "iterations"):
        np.testing.assert_array_equal(out[:, HEAD[name]], ref[:, HEAD[name]], err_msg=f"{case}: {name}")
    cols = [HEAD["u0"] + j for j in range(nc)]
    cols += [HEAD[n] for n in ("residual", "authority", "energy_low", "energy_high")]
    cols += list(range(compiled.N_HEAD, ref.shape[1]))
    a, b = ref[:, cols], out[:, cols]
    np.testing.assert_array_equal(np.isnan(a), np.isnan(b), err_msg=f"{case}: NaN places")
    ok = ~np.isnan(a)
    diff = np.abs(a - b)
    rel = np.where(ok, diff / np.maximum(1.0, np.abs(a)), 0.0)
    rel[:, nc] = np.where(ok[:, nc], diff[:, nc], 0.0)  # the scaled residual: absolute
    worst = float(rel.max()) if rel.size else 0.0
    MEASURED[case] = max(MEASURED.get(case, 0.0), worst)
    assert worst <= TOL, f"{case}: max difference {worst:.3g}"


CASES = [
    # (map, controls, targeted, far: beyond one step's reach for some rows, Deadbeat's options)
    ("geyer", ("touchdown_angle",), (0, 1), 0.0, {}),
    ("geyer", ("touchdown_angle",), (1, 0), 0.0, {}),
    ("geyer", ("touchdown_angle",), (0, 1), 3.0, {}),
    ("geyer", ("touchdown_angle", "k"), (1, 1), 0.0, {}),
    ("geyer", ("touchdown_angle", "k"), (1, 1), 1.5, {}),
    ("iterative", ("touchdown_angle",), (0, 1), 0.0, {}),
    ("iterative", ("touchdown_angle",), (1, 0), 0.0, {}),
    ("iterative", ("touchdown_angle",), (0, 1), 3.0, {}),
    ("iterative", ("touchdown_angle", "k_d"), (1, 1), 0.0, {}),
    ("iterative", ("touchdown_angle", "k_d"), (1, 1), 1.5, {}),
    ("iterative", ("touchdown_angle", "k_d"), (1, 1), 0.0, {"jacobian": "newton"}),
    ("iterative", ("touchdown_angle", "k_d"), (1, 1), 1.5, {"max_evaluations": 7}),
    ("iterative", ("touchdown_angle", "k_c", "k_d"), (1, 1), 0.0, {}),
    ("iterative", ("touchdown_angle", "k_c", "k_d"), (1, 1), 1.5, {"jacobian": "newton"}),
    # apexes 0.3-0.7 l0 high: the map fails over part of the angle's range (APEX_TOO_LOW, FALL)
    ("geyer", ("touchdown_angle",), (0, 1), 0.0, {"heights": (0.3, 0.7)}),
    ("iterative", ("touchdown_angle",), (1, 0), 0.0, {"heights": (0.3, 0.7)}),
    ("iterative", ("touchdown_angle", "k_d"), (1, 1), 0.0, {"heights": (0.3, 0.7)}),
]


def test_layouts_match_ctypes(lib):
    """The ctypes mirrors have the C structs' offsets and sizes, the header the Python constants."""
    at = (ctypes.c_size_t * 64)()
    for fn, struct in ((lib.harness_settings_layout, deadbeat_c.DeadbeatSettings),
                       (lib.harness_work_layout, deadbeat_c.DeadbeatWork)):  # fmt: skip
        fn.restype = ctypes.c_size_t
        n = fn(at)
        want = [getattr(struct, f).offset for f, _ in struct._fields_] + [ctypes.sizeof(struct)]
        assert list(at[: n + 1]) == want, struct.__name__
    lim = (ctypes.c_int * 8)()
    n = lib.harness_limits(lim)
    assert list(lim[:n]) == [
        deadbeat_c.MAX_X,
        deadbeat_c.MAX_P,
        deadbeat_c.MAX_OUT,
        compiled.N_HEAD,
        compiled.REACHED,
        compiled.UNREACHABLE,
        compiled.MAP_FAILED,
    ]


@pytest.mark.parametrize(("name", "controls", "tgt", "far", "options"), CASES)
def test_c_solver_is_the_numba_solver(lib, name, controls, tgt, far, options):
    options = dict(options)
    heights = options.pop("heights", (0.85, 1.3))
    ctl, (apex, jac) = _controller(name, controls, **options)
    seed = zlib.crc32(repr((name, controls, tgt, far)).encode())
    X, Pr, T = _rows(ctl, 150, seed, tgt=tgt, far=far, low=6, heights=heights)
    s = ctl._settings[tgt]
    ref = ctl.solver.run(X, Pr, T, s)
    out, refused = deadbeat_c.solve_rows(lib, apex, jac, X, Pr, T, s)
    assert refused == 0
    case = f"{name} {'+'.join(controls)} {tgt} far {far} {options} heights {heights}"
    _compare(case, ref, out, len(controls))
    statuses = set(out[:, HEAD["plan_status"]].astype(int))
    assert compiled.MAP_FAILED in statuses  # the low rows
    MEASURED[case + " statuses"] = np.bincount(out[:, HEAD["plan_status"]].astype(int), minlength=3).tolist()
    low_apexes = heights[1] < 0.85  # the map fails for most rows, none reaches its target
    assert (compiled.UNREACHABLE if far or low_apexes else compiled.REACHED) in statuses, case


def test_c_solver_matches_the_public_api(lib):
    """A row of slipmaps.deadbeat, solved in C from the same inputs."""
    ctl, (apex, jac) = _controller("iterative", ("touchdown_angle", "k_d"))
    res = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.2)
    angle = default_angle(P, 5.0)
    X = ctl._inputs({"apex_height": 1.0, "apex_speed": 5.0, "ground": 0.0, "touchdown_angle": angle}, 1)
    out, _ = deadbeat_c.solve_rows(
        lib, apex, jac, X, ctl._record[None, :], np.array([[1.0, 5.2]]), ctl._settings[(1, 1)]
    )
    assert out[0, HEAD["plan_status"]] == compiled.REACHED and res.reached
    assert out[0, HEAD["u0"]] == res.touchdown_angle and out[0, HEAD["u0"] + 1] == res.k_d
    assert out[0, HEAD["evaluations"]] == res.evaluations


def test_c_solver_central_differences(lib):
    """The two-stage form's solve (BottomDeadbeat: k_d at the bottom, a half map without a
    Jacobian kernel, central differences) on random bottom states."""
    for aim, tgt in (("both", (1, 1)), ("height", (1, 0)), ("speed", (0, 1))):
        ctl = BottomDeadbeat("iterative-decompression", P, aim=aim)
        apex, _ = map_pointers(ctl.call.spec("apex"))
        rng = np.random.default_rng(7)
        n = 120
        B = np.stack(
            [
                rng.uniform(0.8, 0.95, n) * P.l0,
                np.zeros(n),
                rng.uniform(-0.15, 0.15, n),
                -rng.uniform(0.5, 1.5, n) * math.sqrt(P.g_f / P.l0),
            ],
            axis=1,
        )
        X = np.zeros((n, len(ctl.solver.x)))
        X[:, ctl._state] = B
        T = np.stack([rng.uniform(0.9, 1.2, n), rng.uniform(3.0, 7.0, n)], axis=1)
        T[:, 0] *= tgt[0]
        T[:, 1] *= tgt[1]
        Pr = ctl._records(None, n)
        ref = ctl.solver.run(X, Pr, T, ctl._settings)
        out, refused = deadbeat_c.solve_rows(lib, apex, None, X, Pr, T, ctl._settings)
        assert refused == 0
        _compare(f"iterative-decompression k_d {aim}", ref, out, 1)


def test_c_solver_refuses_what_its_buffers_cannot_hold(lib):
    ctl, (apex, jac) = _controller("geyer", ("touchdown_angle",))
    X, Pr, T = _rows(ctl, 2, seed=1, tgt=(0, 1))
    big = deadbeat_c.c_settings(ctl._settings[(0, 1)])
    big.n_wrt = deadbeat_c.MAX_OUT  # a Jacobian row beyond the buffer
    for args, s in (((X, Pr), big), ((np.zeros((2, deadbeat_c.MAX_X + 1)), Pr), ctl._settings[(0, 1)])):
        out, refused = deadbeat_c.solve_rows(lib, apex, jac, *args, T, s)
        assert refused == 2
        assert (out[:, HEAD["plan_status"]] == compiled.MAP_FAILED).all()
        assert (out[:, HEAD["map_status"]] == int(Status.INVALID_INPUT)).all()
        assert (out[:, HEAD["evaluations"]] == 0).all()
    out, refused = deadbeat_c.solve_rows(lib, apex, None, X, Pr, T, ctl._settings[(0, 1)])  # no Jacobian
    assert refused == 2


def _reachable(ctl, controls, tgt, n, seed):
    """n rows whose targets the map reaches: its next apex at random controls (the angle within
    0.04 rad of the default, a stiffness within 15 % of nominal; rows where the map fails dropped):
    the cold rows (X, P: the default start), the warm rows (the controls that reach the target
    moved by up to 0.01 rad and 2 %, as a run starts from the previous step's) and the targets."""
    X, Pr, _ = _rows(ctl, n, seed, tgt=tgt)
    rng = np.random.default_rng(seed + 1)
    apex = ctl.call.spec("apex_return").functions()[0]
    T = np.zeros((n, 2))
    Xw, Pw = X.copy(), np.repeat(Pr, n, axis=0)
    keep = np.zeros(n, dtype=bool)
    out = np.empty(len(ctl.outputs))
    for i in range(n):
        x, p = X[i].copy(), Pr[0].copy()
        for c in controls:
            in_p, at = ctl.solver.place(CONTROLS[c])
            if in_p:
                p[at] *= rng.uniform(0.85, 1.15)
                Pw[i, at] = p[at] * rng.uniform(0.98, 1.02)
            else:
                x[at] += rng.uniform(-0.04, 0.04)
                Xw[i, at] = x[at] + rng.uniform(-0.01, 0.01)
        keep[i] = apex(x, p, out) == 0
        T[i] = out[ctl._out_h] * tgt[0], out[ctl._out_v] * tgt[1]
    c = np.ascontiguousarray
    return c(X[keep]), Pr, c(Xw[keep]), c(Pw[keep]), c(T[keep])


def _time_c(lib, apex, jac, X, Pr, T, cs, reps=20):
    """Seconds per C solve: the best of 5 C loops over the rows (the rows' outputs, too)."""
    OUT = np.empty((X.shape[0], compiled.N_HEAD + cs.n_out))
    f = lib.harness_time
    vp, i = ctypes.c_void_p, ctypes.c_int
    f.argtypes = [vp, vp, vp, i, i, vp, i, i, vp, vp, vp, i]
    args = (apex, jac, X.ctypes.data, X.shape[0], X.shape[1], Pr.ctypes.data, Pr.shape[0], Pr.shape[1],
            T.ctypes.data, ctypes.addressof(cs), OUT.ctypes.data, reps)  # fmt: skip
    return min(f(*args) for _ in range(5)), OUT


def _time_numba(ctl, X, Pr, T, s, reps=20):
    """Seconds per numba solve: its compiled rows entry point (one thread), the best of 5."""
    import time

    OUT = np.empty((X.shape[0], ctl.solver.width))
    ctl.solver._rows(X, Pr, T, s, OUT)
    best = math.inf
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(reps):
            ctl.solver._rows(X, Pr, T, s, OUT)
        best = min(best, (time.perf_counter() - t0) / (reps * X.shape[0]))
    return best


@pytest.mark.skipif(not os.environ.get("SLIPMAPS_C_TIMING"), reason="SLIPMAPS_C_TIMING=1 times the C solve")
def test_c_timing(lib):
    """Microseconds per C solve from a C loop, beside the numba solve of the same rows, on targets
    the map reaches (:func:`_reachable`): cold (from the default angle and nominal stiffness) and
    warm (started near the controls that reach the target, as a run's steps are); and a map
    kernel call alone. The warm rows are also compared with the numba solver's."""
    with open("/proc/loadavg") as fh:
        print("\nload before:", fh.read().strip())
    for name, controls, tgt in (
        ("geyer", ("touchdown_angle",), (0, 1)),
        ("geyer", ("touchdown_angle", "k"), (1, 1)),
        ("iterative", ("touchdown_angle",), (0, 1)),
        ("iterative", ("touchdown_angle", "k_d"), (1, 1)),
    ):
        ctl, (apex, jac) = _controller(name, controls)
        s = ctl._settings[tgt]
        cs = deadbeat_c.c_settings(s)
        X, Pr, Xw, Pw, T = _reachable(ctl, controls, tgt, 400, seed=3)
        cold, _ = _time_c(lib, apex, jac, X, Pr, T, cs)
        cold_n = _time_numba(ctl, X, Pr, T, s)
        warm, OUT = _time_c(lib, apex, jac, Xw, Pw, T, cs)
        warm_n = _time_numba(ctl, Xw, Pw, T, s)
        _compare(f"{name} {'+'.join(controls)} warm", ctl.solver.run(Xw, Pw, T, s), OUT, len(controls))
        nj, ne = OUT[:, HEAD["jacobians"]].mean(), OUT[:, HEAD["evaluations"]].mean()
        reached = (OUT[:, HEAD["plan_status"]] == compiled.REACHED).mean()
        # one kernel call: the apex map alone, from C
        f = lib.harness_time_map
        f.restype = ctypes.c_double
        f.argtypes = [ctypes.c_void_p] * 4 + [ctypes.c_int]
        w = np.empty(cs.n_out * (1 + max(cs.n_wrt, 0)))
        t_apex = min(f(apex, Xw.ctypes.data, Pw.ctypes.data, w.ctypes.data, 20000) for _ in range(5))
        t_jac = min(f(jac, Xw.ctypes.data, Pw.ctypes.data, w.ctypes.data, 20000) for _ in range(5))
        own = warm - nj * t_jac - ne * t_apex  # rough: the kernels timed on one row
        with open("/proc/loadavg") as fh:
            load = fh.read().split()[0]
        print(
            f"{name} {'+'.join(controls)}: warm C {warm * 1e6:.2f} us (numba {warm_n * 1e6:.2f}), "
            f"{nj:.2f} Jacobian + {ne:.2f} apex calls (the solver's own about {own * 1e6:.2f} us), "
            f"{len(T)} rows, reached {reached:.0%}; "
            f"cold C {cold * 1e6:.2f} us (numba {cold_n * 1e6:.2f}); "
            f"apex call {t_apex * 1e6:.3f} us, Jacobian call {t_jac * 1e6:.3f} us; load {load}"
        )


def test_report_measured():
    print("\nmax differences, C vs numba (and the plan statuses' counts):")
    for k, v in MEASURED.items():
        print(f"  {k}: {v}")


@pytest.mark.parametrize("overrides", [{}, {"two_stage": True}], ids=["apex", "two-stage"])
def test_stairs_run_with_the_c_controller(lib, monkeypatch, overrides):
    """The stairs scenario (examples/stairs.toml: the exact plant in Python) run with every deadbeat
    solve in C (the C solver on the exported C maps, in place of the numba solver; two-stage: k_d
    chosen again at the bottom, on the decompression half's C kernel) takes the same steps as
    ``slipmaps run``: the same statuses, controls and states (measured: to the last bit)."""
    from pathlib import Path

    from slipmaps.runtime.control import deadbeat

    scenario = Path(__file__).resolve().parent.parent / "examples" / "stairs.toml"
    reference = slipmaps.run(scenario, **overrides).columns()
    calls = []

    def c_bind(apex, jac):
        a = ctypes.cast(getattr(lib, f"slipmaps_{apex.__name__}_v"), ctypes.c_void_p).value
        j = ctypes.cast(getattr(lib, f"slipmaps_{jac.__name__}_v"), ctypes.c_void_p).value

        def rows(X, P, T, s, OUT):
            out, refused = deadbeat_c.solve_rows(lib, a, j, X, P, T, s)
            assert refused == 0
            OUT[:] = out
            calls.append(len(X))

        return rows

    monkeypatch.setattr(compiled, "bind", c_bind)
    deadbeat._prepared.cache_clear()
    try:
        with_c = slipmaps.run(scenario, **overrides).columns()
    finally:
        deadbeat._prepared.cache_clear()
    assert calls, "the run never called the C solver"
    if overrides.get("two_stage"):
        assert np.isfinite(reference["bottom_us"]).any(), "the two-stage run never solved at the bottom"
    assert len(with_c["step"]) == len(reference["step"]) == 14
    timings = {"solve_us", "bottom_us"}  # wall-clock times of the solves, not results
    assert timings <= set(reference)
    for name, ref in reference.items():
        if name in timings:
            continue
        got = with_c[name]
        if np.asarray(ref).dtype.kind in "fc":
            np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-12, err_msg=name)
        else:
            np.testing.assert_array_equal(got, ref, err_msg=name)


def test_example_c_builds_and_runs(c_export, tmp_path):
    """examples/c/main.c (docs/c_export.md's example) compiles warning-free against the exported
    library and runs its 12 steps, the plan reaching the target on most."""
    import subprocess
    from pathlib import Path

    from slipmaps.runtime.export.clib import STRICT, compiler

    main = Path(__file__).resolve().parent.parent / "examples" / "c" / "main.c"
    exe = tmp_path / "run_deadbeat"
    objects = [str(c_export / "slipmaps.o"), str(c_export / "slipmaps_deadbeat.o")]
    build = [compiler(), *STRICT, "-I", str(c_export), str(main), *objects, "-o", str(exe), "-lm"]
    subprocess.run(build, check=True, capture_output=True, text=True)
    run = subprocess.run([str(exe)], check=True, capture_output=True, text=True)
    rows = run.stdout.splitlines()[1:]
    assert len(rows) == 12, run.stdout
    assert sum(r.split()[6] == "ok" for r in rows) >= 6, run.stdout
