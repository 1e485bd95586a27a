"""Layer 2 of CODEGEN.md: the generation pipeline and the generated kernels.

- Determinism: `build_files()` is reproducible within a process and across processes with
  different hash seeds (set iteration order must not leak into the output).
- Drift: the committed files are what the sources produce (`slipmaps generate --check`), and a
  hand edit, a missing file or a stale file is reported.
- Every generated kernel is a numba dispatcher (no silent pure-Python fallback) and runs.
- Each kernel agrees with `sympy.lambdify` of the very expressions it was generated from and with
  its own `.py_func`, at random in-domain points; lambdify with CSE on and off agree.
- Headers and status codes are what the sources say.

Tolerances. The kernel and the lambdified reference evaluate the same expression arranged
differently (canonical CSE and integer powers in the kernel, SymPy's default printing in the
reference), a few dozen float64 operations each, so they differ by a few ulps times the condition
number of the expression. The sampled domain keeps that condition number small: |q_rd_td| >= 0.3
m/s keeps the squared amplitude b^2 (a difference of energies) well away from cancellation, and
sin(phase) stays inside [-0.99, 0.99] where asin is well conditioned. Measured worst relative
discrepancies (numpy 2.4, numba 0.68, sympy 1.14): 9e-16 kernel vs lambdify, 2e-15 lambdify with
vs without CSE, 3e-15 trajectory kernel vs stance-map kernel. RTOL = 1e-12 leaves more than two
orders of margin and still catches any wrong term, sign or branch (those are O(1) errors).
Near-zero outputs (a leg angle crossing 0, the bottom rate that is 0 by construction) get an
absolute floor of RTOL times the output's natural magnitude. `.py_func` is the same source run by
CPython; numba compiles it without fastmath, so the two agree to the last ulp (bitwise today;
RTOL_PYFUNC allows a few ulps for libm differences).
"""

from __future__ import annotations

import hashlib
import inspect
import json
import math
import os
import re
import shutil
import subprocess
import sys
from functools import cache

import numpy as np
import pytest
import sympy as sp
from numba.core.registry import CPUDispatcher
from slipmaps.derive import flight as d_flight
from slipmaps.derive import generate, mechanics
from slipmaps.derive import geyer as d_geyer
from slipmaps.derive import symbols as S
from slipmaps.derive.status import STATUS_CODES
from slipmaps.generated import flight as g_flight
from slipmaps.generated import geyer as g_geyer
from slipmaps.generated import slip_model as g_slip
from slipmaps.generated.status import MESSAGES, Status

RTOL = 1e-12
RTOL_PYFUNC = 1e-14
N_POINTS = 20
KERNEL_MODULES = (g_slip, g_flight, g_geyer)


# ----------------------------------------------------------------------------------------------
# Determinism and drift
# ----------------------------------------------------------------------------------------------
def _digest(files: dict[str, str]) -> str:
    return hashlib.sha256(json.dumps(files, sort_keys=True).encode()).hexdigest()


_SUBPROCESS = (
    "import hashlib, json\n"
    "from slipmaps.derive.generate import build_files\n"
    "print(hashlib.sha256(json.dumps(build_files(), sort_keys=True).encode()).hexdigest())\n"
)


def test_build_files_deterministic_in_process():
    first = generate.build_files()
    second = generate.build_files()
    assert first == second


def test_build_files_independent_of_hash_seed():
    """Fresh interpreters with other PYTHONHASHSEEDs produce byte-identical files."""
    procs = []
    for seed in ("1", "123"):
        env = {**os.environ, "PYTHONHASHSEED": seed}
        procs.append(
            (
                seed,
                subprocess.Popen(
                    [sys.executable, "-c", _SUBPROCESS],
                    env=env,
                    cwd=generate.ROOT,
                    stdout=subprocess.PIPE,
                    stderr=subprocess.PIPE,
                    text=True,
                ),
            )
        )
    try:
        expected = _digest(generate.build_files())
        for seed, proc in procs:
            out, err = proc.communicate(timeout=120)
            assert proc.returncode == 0, err
            assert out.strip() == expected, f"PYTHONHASHSEED={seed} gives different generated files"
    finally:
        for _, proc in procs:
            if proc.poll() is None:
                proc.kill()
                proc.communicate()


def test_generated_files_current():
    """What `slipmaps generate --check` runs: committed files equal the sources' output, none stale."""
    problems = generate.check()
    assert problems == [], "\n".join(problems) + "\nrun `slipmaps generate`"


def test_generate_check_entry_point(capsys):
    assert generate.main(check_only=True) == 0
    assert "generated files are current" in capsys.readouterr().out


@pytest.fixture
def checkout_copy(tmp_path, monkeypatch):
    """A copy of the generated files, docs and README with generate.ROOT pointed at it."""
    files = generate.build_files()
    root = tmp_path / "checkout"
    for rel in files:
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(generate.ROOT / rel, root / rel)
    shutil.copy2(generate.ROOT / "pyproject.toml", root / "pyproject.toml")
    monkeypatch.setattr(generate, "ROOT", root)
    monkeypatch.setattr(generate, "GENERATED", root / "generated")
    return root, files


def test_check_clean_copy(checkout_copy):
    _, files = checkout_copy
    assert generate.check(files=files) == []


def test_hand_edit_detected(checkout_copy):
    root, files = checkout_copy
    path = root / "generated" / "geyer.py"
    text = path.read_text()
    edited = text.replace("b_q_rd = 0.0", "b_q_rd = 0.0  # tweaked", 1)
    assert edited != text
    path.write_text(edited)
    problems = generate.check(files=files)
    assert len(problems) == 1
    assert "a/generated/geyer.py (committed)" in problems[0]
    assert "-    b_q_rd = 0.0  # tweaked" in problems[0]
    assert "+    b_q_rd = 0.0\n" in problems[0]


def test_edited_docs_table_detected(checkout_copy):
    root, files = checkout_copy
    path = root / "docs" / "equations.md"
    path.write_text(path.read_text().replace("| corrected |", "| verified |", 1))
    problems = generate.check(files=files)
    assert len(problems) == 1 and "docs/equations.md" in problems[0]


def test_missing_and_stale_files_detected(checkout_copy):
    root, files = checkout_copy
    (root / "generated" / "flight.py").unlink()
    (root / "generated" / "old_kernels.py").write_text("# left over\n")
    problems = generate.check(files=files)
    assert any("generated/flight.py" in p for p in problems)
    assert any("generated/old_kernels.py: stale" in p for p in problems)


def test_write_touches_only_changed_files(checkout_copy):
    """`slipmaps generate` rewrites only what changed (numba's cache keys on mtime) and drops stale files."""
    root, files = checkout_copy
    assert generate.write(files) == []
    (root / "generated" / "flight.py").write_text("# hand edit\n")
    (root / "generated" / "old_kernels.py").write_text("# left over\n")
    mtime = (root / "generated" / "geyer.py").stat().st_mtime_ns
    touched = generate.write(files)
    assert sorted(touched) == ["generated/flight.py", "generated/old_kernels.py"]
    assert (root / "generated" / "flight.py").read_text() == files["generated/flight.py"]
    assert not (root / "generated" / "old_kernels.py").exists()
    assert (root / "generated" / "geyer.py").stat().st_mtime_ns == mtime
    assert generate.check(files=files) == []


# ----------------------------------------------------------------------------------------------
# Headers and status codes
# ----------------------------------------------------------------------------------------------
_TIMESTAMP = re.compile(
    r"\b\d{4}-\d{2}-\d{2}\b|\b\d{1,2}:\d{2}(:\d{2})?\b|\b(19|20)\d{2}\b|generated (on|at)\b", re.IGNORECASE
)


def _generated_py():
    return sorted(rel for rel in generate.build_files() if rel.startswith("generated/"))


@pytest.mark.parametrize("rel", _generated_py())
def test_generated_header(rel):
    text = generate.build_files()[rel]
    header = text.split('"""', 1)[0]
    assert "GENERATED FILE -- DO NOT EDIT" in header
    source = re.search(r"^# Source:\s+(\S+)$", header, re.MULTILINE)
    assert source, f"{rel}: header does not name its source"
    assert (generate.ROOT / source.group(1)).is_file(), source.group(1)
    template = re.search(r"^# Template:\s+(\S+)$", header, re.MULTILINE)
    assert template and (generate.ROOT / template.group(1)).is_file()
    assert re.search(r"^# Rebuild:\s+slipmaps generate\b", header, re.MULTILINE)
    assert "slipmaps generate --check" in header
    assert f"sympy {sp.__version__}" in header
    assert not _TIMESTAMP.search(header), f"{rel}: header contains a timestamp-like string"


def test_sympy_pinned_version_used():
    """The header's tool version must be the pinned one, or the drift check compares noise."""
    pyproject = (generate.ROOT / "pyproject.toml").read_text()
    pins = set(re.findall(r'"sympy==([0-9.]+)"', pyproject))
    assert pins == {sp.__version__}


def test_docs_table_header():
    text = generate.build_files()["docs/equations.md"]
    assert text.startswith("<!-- GENERATED by `slipmaps generate`")
    assert not _TIMESTAMP.search(text.splitlines()[0])


def test_status_enum_matches_source():
    assert [(s.name, s.value) for s in Status] == [(n, c) for n, c, _ in STATUS_CODES]
    assert MESSAGES == {c: msg for _, c, msg in STATUS_CODES}
    codes = [c for _, c, _ in STATUS_CODES]
    assert codes == list(range(len(codes))), "codes are append-only and consecutive"
    assert STATUS_CODES[0][:2] == ("OK", 0)


@pytest.mark.parametrize("mod", KERNEL_MODULES, ids=lambda m: m.__name__.rsplit(".", 1)[-1])
def test_module_status_constants_match(mod):
    consts = {n[len("STATUS_") :]: v for n, v in vars(mod).items() if n.startswith("STATUS_")}
    assert consts == {n: c for n, c, _ in STATUS_CODES}


# ----------------------------------------------------------------------------------------------
# Every kernel is a numba dispatcher and runs
# ----------------------------------------------------------------------------------------------
#: An in-domain value for each kernel argument name (human runner scale; all kernels return OK).
NOMINAL = {
    "q_r": 0.95,
    "q_rd": -0.5,
    "q_th": 0.3,
    "q_thd": -3.0,
    "m": 80.0,
    "l0": 1.0,
    "k": 20_000.0,
    "g_s": 9.81,
    "g_f": 9.81,
    "b_x": -0.3,
    "b_xd": 5.0,
    "b_y": 0.9,
    "b_yd": -1.0,
    "b_y_apex": 1.0,
    "b_xd_apex": 5.0,
    "q_th_td": 0.3,
    "q_r_td": 1.0,
    "q_rd_td": -0.5,
    "q_thd_td": -3.0,
    "q_r_lo": 1.0,
    "t": 0.05,
}


def _kernels():
    out = []
    for mod in KERNEL_MODULES:
        for name, obj in vars(mod).items():
            if isinstance(obj, CPUDispatcher) and obj.py_func.__module__ == mod.__name__:
                out.append(pytest.param(mod, name, id=f"{mod.__name__.rsplit('.', 1)[-1]}.{name}"))
    return out


KERNELS = _kernels()


def test_kernels_found():
    """The kernels this file exercises exist (a renamed or dropped kernel fails here)."""
    names = {p.values[1] for p in KERNELS}
    scalar = {"stance_polar_rhs", "stance_cartesian_rhs", "stance_energy", "polar_to_cartesian"}
    scalar |= {"cartesian_to_polar", "apex_to_touchdown", "liftoff_to_apex", "geyer_stance"}
    scalar |= {"geyer_stance_state_at", "geyer_apex_return"}
    batch = {"apex_to_touchdown", "liftoff_to_apex", "geyer_stance", "geyer_stance_state_at"}
    batch = {f"{n}_batch" for n in batch | {"geyer_apex_return"}}
    assert scalar | batch <= names


@pytest.mark.parametrize("mod", KERNEL_MODULES, ids=lambda m: m.__name__.rsplit(".", 1)[-1])
def test_no_pure_python_functions(mod):
    """Every function a generated module defines is jitted: no silent fallback to Python."""
    plain = [
        n
        for n, o in vars(mod).items()
        if inspect.isfunction(o) and getattr(o, "__module__", "") == mod.__name__
    ]
    assert plain == []


@pytest.mark.parametrize(("mod", "name"), KERNELS)
def test_kernel_is_dispatcher_and_runs(mod, name):
    kern = getattr(mod, name)
    assert isinstance(kern, CPUDispatcher)
    if not name.endswith("_batch"):
        args = [NOMINAL[p] for p in inspect.signature(kern.py_func).parameters]
        res = kern(*args)
        res = res if isinstance(res, tuple) else (res,)
        assert all(math.isfinite(x) for x in res), res
        if mod is not g_slip:  # flight and Geyer kernels end with a status code
            assert res[-1] == Status.OK, res
        return
    scalar = getattr(mod, name.removesuffix("_batch"))
    params = list(inspect.signature(scalar.py_func).parameters)
    assert list(inspect.signature(kern.py_func).parameters) == [*params, "out", "status"]
    n = 3
    cols = [np.full(n, NOMINAL[p]) for p in params]
    cols[0] = cols[0] * np.array([1.0, 0.99, 0.98])  # distinct rows
    ref = [scalar(*(c[i] for c in cols)) for i in range(n)]
    out = np.full((n, len(ref[0]) - 1), -1.0)
    status = np.full(n, -1, dtype=np.int64)
    kern(*cols, out, status)
    np.testing.assert_array_equal(out, np.array([r[:-1] for r in ref]))
    np.testing.assert_array_equal(status, [r[-1] for r in ref])
    assert status[0] == Status.OK


# ----------------------------------------------------------------------------------------------
# Kernel vs lambdify of the derived expressions vs .py_func
# ----------------------------------------------------------------------------------------------
@cache
def _lambdified(expr, cse):
    expr = sp.sympify(expr)
    syms = sorted(expr.free_symbols, key=lambda s: s.name)
    fn = sp.lambdify(syms, expr, modules="math", cse=cse)
    names = [s.name for s in syms]
    return lambda env: float(fn(*(env[n] for n in names)))


def ev(expr, env, cse=False):
    """Value of a derived expression, its free symbols looked up by name in ``env``."""
    return _lambdified(sp.sympify(expr), cse)(env)


def assert_close(actual, expected, rtol, scale=None, what=""):
    """|actual - expected| <= rtol * (|expected| + scale), scale a per-column magnitude (broadcast)."""
    actual, expected = np.asarray(actual, dtype=float), np.asarray(expected, dtype=float)
    floor = 0.0 if scale is None else np.asarray(scale, dtype=float)
    err = np.abs(actual - expected)
    bad = ~(err <= rtol * (np.abs(expected) + floor))
    assert not bad.any(), (
        f"{what}: {bad.sum()} mismatches; worst |diff|/(|ref|+scale) = "
        f"{np.max(err / (np.abs(expected) + floor + 1e-300)):.3g} (rtol {rtol:g})\n"
        f"actual[bad]={actual[bad]}\nexpected[bad]={expected[bad]}"
    )


def _rng(name):
    return np.random.default_rng(int(hashlib.sha256(name.encode()).hexdigest()[:8], 16))


def _params(rng):
    m = rng.uniform(2.0, 100.0)
    l0 = rng.uniform(0.25, 1.2)
    g_s = rng.uniform(9.0, 10.0)
    k = rng.uniform(10.0, 40.0) * m * g_s / l0  # dimensionless stiffness 10-40
    return {"m": m, "l0": l0, "k": k, "g_s": g_s, "g_f": rng.uniform(9.0, 10.0)}


def _assert_agree(kernel, args_names, points, reference, n_out, rtol=RTOL, scales=None):
    """kernel(*args) vs kernel.py_func(*args) vs reference(env, cse) for cse in (False, True).

    ``scales(env)`` gives each output's natural magnitude (for outputs that are 0 by construction);
    by default the largest |reference| of the output over the sample.
    """
    got, py, ref, ref_cse = [], [], [], []
    for env in points:
        args = [env[n] for n in args_names]
        r = kernel(*args)
        got.append(r if isinstance(r, tuple) else (r,))
        r = kernel.py_func(*args)
        py.append(r if isinstance(r, tuple) else (r,))
        ref.append(reference(env, False))
        ref_cse.append(reference(env, True))
    got, py = np.array(got, dtype=float), np.array(py, dtype=float)
    ref, ref_cse = np.array(ref, dtype=float), np.array(ref_cse, dtype=float)
    assert got.shape[1] in (n_out, n_out + 1)
    if got.shape[1] == n_out + 1:  # status column
        assert (got[:, -1] == Status.OK).all(), got[:, -1]
        assert (py[:, -1] == Status.OK).all()
        got, py = got[:, :-1], py[:, :-1]
    assert np.isfinite(ref).all()
    scale = np.abs(ref).max(axis=0)
    if scales is not None:
        scale = np.maximum(scale, np.array([scales(env) for env in points]))
    assert_close(ref_cse, ref, RTOL, scale, "lambdify cse on vs off")
    assert_close(got, ref, rtol, scale, f"{kernel.__name__} vs lambdify")
    assert_close(got, py, RTOL_PYFUNC, scale, f"{kernel.__name__} vs .py_func")
    return got


def _polar_points(name, n=N_POINTS):
    rng = _rng(name)
    pts = []
    for _ in range(n):
        p = _params(rng)
        p.update(
            q_r=rng.uniform(0.6, 1.0) * p["l0"],
            q_rd=rng.uniform(-3.0, 3.0),
            q_th=rng.uniform(-0.7, 0.7),
            q_thd=rng.uniform(-6.0, 6.0),
        )
        pts.append(p)
    return pts


POLAR = ("q_r", "q_rd", "q_th", "q_thd")
PARAMS = ("m", "l0", "k", "g_s")
CART = ("b_x", "b_xd", "b_y", "b_yd")


def test_stance_polar_rhs_matches_derivation():
    exprs = mechanics.stance_polar_rhs()
    _assert_agree(
        g_slip.stance_polar_rhs,
        POLAR + PARAMS,
        _polar_points("polar_rhs"),
        lambda env, cse: [ev(e, env, cse) for e in exprs],
        4,
    )


def test_stance_cartesian_rhs_matches_derivation():
    exprs = mechanics.stance_cartesian_rhs()
    pts = []
    for env in _polar_points("cart_rhs"):
        env.update(zip(CART, g_slip.polar_to_cartesian(*(env[n] for n in POLAR)), strict=True))
        pts.append(env)
    got = _assert_agree(
        g_slip.stance_cartesian_rhs,
        CART + PARAMS,
        pts,
        lambda env, cse: [ev(e, env, cse) for e in exprs],
        4,
    )
    # The same dynamics in both coordinates: Cartesian accelerations from the polar vector field.
    for env, cart in zip(pts, got, strict=True):
        r, rd, th, thd = (env[n] for n in POLAR)
        _, rdd, _, thdd = g_slip.stance_polar_rhs(r, rd, th, thd, *(env[n] for n in PARAMS))
        xdd = -(rdd - r * thd**2) * math.sin(th) - (r * thdd + 2 * rd * thd) * math.cos(th)
        ydd = (rdd - r * thd**2) * math.cos(th) - (r * thdd + 2 * rd * thd) * math.sin(th)
        scale = env["k"] / env["m"] * env["l0"] + env["g_s"]
        assert_close(cart[[1, 3]], [xdd, ydd], 1e-12, scale, "Cartesian vs polar accelerations")


def test_stance_energy_matches_derivation():
    expr = mechanics.stance_energy()
    _assert_agree(
        g_slip.stance_energy,
        POLAR + PARAMS,
        _polar_points("energy"),
        lambda env, cse: [ev(expr, env, cse)],
        1,
    )


def test_coordinate_maps_match_derivation_and_invert():
    p2c, c2p = mechanics.polar_to_cartesian(), mechanics.cartesian_to_polar()
    pts = _polar_points("coords")
    cart = _assert_agree(
        g_slip.polar_to_cartesian, POLAR, pts, lambda env, cse: [ev(e, env, cse) for e in p2c], 4
    )
    cpts = [dict(zip(CART, row, strict=True)) for row in cart]
    back = _assert_agree(
        g_slip.cartesian_to_polar, CART, cpts, lambda env, cse: [ev(e, env, cse) for e in c2p], 4
    )
    polar = np.array([[env[n] for n in POLAR] for env in pts])
    assert_close(back, polar, 1e-12, np.abs(polar).max(axis=0), "cartesian_to_polar(polar_to_cartesian(x))")


def _apex_points(name, n=N_POINTS):
    rng = _rng(name)
    pts = []
    for _ in range(n):
        p = _params(rng)
        q_th_td = rng.uniform(-0.6, 0.6)
        q_r_td = rng.uniform(0.8, 1.0) * p["l0"]
        p.update(
            q_th_td=q_th_td,
            q_r_td=q_r_td,
            b_y_apex=q_r_td * math.cos(q_th_td) + rng.uniform(0.02, 0.5) * p["l0"],
            b_xd_apex=rng.uniform(0.5, 8.0),
        )
        pts.append(p)
    return pts


A2T_ARGS = ("b_y_apex", "b_xd_apex", "q_th_td", "q_r_td", "g_f")


def _apex_to_touchdown_ref(env, cse):
    atd = d_flight.apex_to_touchdown()
    env = {**env, atd["drop_symbol"].name: ev(atd["drop"], env, cse)}
    return [ev(e, env, cse) for e in atd["state"]] + [ev(atd["t_flight"], env, cse)]


def test_apex_to_touchdown_matches_derivation():
    pts = _apex_points("a2t")
    got = _assert_agree(g_flight.apex_to_touchdown, A2T_ARGS, pts, _apex_to_touchdown_ref, 5)
    # Physics of the descent: falling speed sqrt(2 g drop), energy of the flight conserved.
    for env, row in zip(pts, got, strict=True):
        _, xd, _, yd = g_slip.polar_to_cartesian(*row[:4])
        assert xd == pytest.approx(env["b_xd_apex"], rel=1e-12)
        drop = env["b_y_apex"] - env["q_r_td"] * math.cos(env["q_th_td"])
        assert yd == pytest.approx(-math.sqrt(2 * env["g_f"] * drop), rel=1e-12)
        assert row[4] == pytest.approx(-yd / env["g_f"], rel=1e-12)


def _liftoff_points(name, n=N_POINTS):
    """Liftoff states moving up and forward (the domain where liftoff_to_apex returns OK)."""
    rng = _rng(name)
    pts = []
    while len(pts) < n:
        p = _params(rng)
        p.update(
            q_r=rng.uniform(0.8, 1.0) * p["l0"],
            q_rd=rng.uniform(0.2, 3.0),
            q_th=rng.uniform(-0.6, -0.05),
            q_thd=rng.uniform(-6.0, -0.5),
        )
        if g_flight.liftoff_to_apex(*(p[n] for n in POLAR), p["g_f"])[-1] == Status.OK:
            pts.append(p)
    return pts


def _liftoff_to_apex_ref(env, cse):
    lta = d_flight.liftoff_to_apex()
    env = {**env, **{n: ev(e, env, cse) for n, e in zip(CART, lta["liftoff_cartesian"], strict=True)}}
    return [ev(lta[key], env, cse) for key in ("b_y_apex", "b_xd_apex", "t_flight", "dx_flight")]


def test_liftoff_to_apex_matches_derivation():
    pts = _liftoff_points("l2a")
    got = _assert_agree(g_flight.liftoff_to_apex, POLAR + ("g_f",), pts, _liftoff_to_apex_ref, 4)
    for env, row in zip(pts, got, strict=True):
        _, xd, y, yd = g_slip.polar_to_cartesian(*(env[n] for n in POLAR))
        # Energy per unit mass is conserved in flight: g y + yd^2 / 2 = g * apex height.
        assert row[0] * env["g_f"] == pytest.approx(env["g_f"] * y + yd**2 / 2, rel=1e-12)
        assert row[3] == pytest.approx(xd * row[2], rel=1e-12)


# Geyer et al.'s stance map ---------------------------------------------------------------------
STANCE_ARGS = ("q_r_td", "q_rd_td", "q_th_td", "q_thd_td") + PARAMS


def _touchdown_points(name, n=N_POINTS):
    """Random touchdown states (compressing, human/robot scales) where geyer_stance returns OK."""
    rng = _rng(name)
    pts = []
    while len(pts) < n:
        p = _params(rng)
        l0 = p["l0"]
        p.update(
            q_r_td=l0 * rng.choice([1.0, rng.uniform(0.93, 1.0)]),
            q_rd_td=-rng.uniform(0.3, 2.5) * math.sqrt(p["g_s"] * l0),
            q_th_td=rng.uniform(-0.5, 0.5),
            q_thd_td=-rng.uniform(0.5, 2.0) * math.sqrt(p["g_s"] / l0),
            q_r_lo=l0 * rng.choice([1.0, rng.uniform(0.93, 1.0)]),
        )
        res = g_geyer.geyer_stance(*(p[k] for k in STANCE_ARGS), p["q_r_lo"])
        s_ok = res[-1] == Status.OK
        if s_ok and _geyer_reference(p, False)["max_abs_s"] <= 0.99:
            pts.append(p)
    return pts


def _geyer_reference(env, cse):
    """Eqs (7)-(19) evaluated one derivation step at a time with lambdify, as plain floats."""
    td = d_geyer.touchdown_parameters()
    sol = d_geyer.radial_solution_parameters()
    gen = d_geyer.stance_time_general()
    th_expr, t_td = d_geyer.leg_angle()
    exact_rate, _ = d_geyer.angular_rate()
    rho_t = d_geyer.radial_solution()
    rho_d_t = sp.diff(rho_t, S.t)
    env = dict(env)
    env["omega0"] = ev(td["omega0"], env, cse)
    env["omega"] = ev(td["omega"], env, cse)
    env["epsilon"] = ev(td["epsilon"], env, cse)
    for key in ("omega0_hat", "a", "b2"):
        env[key] = ev(sol[key], env, cse)
    env["b"] = math.sqrt(env["b2"])
    assert ev(sol["b"], env, cse) == pytest.approx(env["b"], rel=1e-12)
    phases = {key: ev(gen[key], env, cse) for key in ("phase_td", "phase_b", "phase_lo")}
    w_hat, l0 = env["omega0_hat"], env["l0"]
    env[t_td.name] = phases["phase_td"] / w_hat

    def state_at_abs_time(t_abs):
        e = {**env, "t": t_abs}
        rho = ev(rho_t, e, cse)
        return [
            l0 * (1 + rho),
            l0 * ev(rho_d_t, e, cse),
            ev(th_expr, e, cse),
            ev(exact_rate, {**e, "rho": rho}),
        ]

    s_td = (env["q_r_td"] / l0 - 1 - env["a"]) / env["b"]
    s_lo = (env["q_r_lo"] / l0 - 1 - env["a"]) / env["b"]
    return {
        "env": env,
        "phases": phases,
        "state_at_abs_time": state_at_abs_time,
        "max_abs_s": max(abs(s_td), abs(s_lo)),
        "t_bottom": ev(gen["t_bottom"], env, cse),
        "t_stance": ev(gen["t_stance"], env, cse),
    }


def _geyer_scales(env):
    """Natural magnitudes of (t_bottom, t_stance, bottom state, liftoff state)."""
    t_scale = 1.0 / math.sqrt(env["k"] / env["m"])
    state = [env["l0"], abs(env["q_rd_td"]), 1.0, abs(env["q_thd_td"])]
    return [t_scale, t_scale, *state, *state]


def _geyer_stance_ref(env, cse):
    ref = _geyer_reference(env, cse)
    w_hat = ref["env"]["omega0_hat"]
    bottom = ref["state_at_abs_time"](ref["phases"]["phase_b"] / w_hat)
    liftoff = ref["state_at_abs_time"](ref["phases"]["phase_lo"] / w_hat)
    return [ref["t_bottom"], ref["t_stance"], *bottom, *liftoff]


def test_geyer_stance_matches_derivation():
    pts = _touchdown_points("geyer")
    got = _assert_agree(
        g_geyer.geyer_stance, STANCE_ARGS + ("q_r_lo",), pts, _geyer_stance_ref, 10, scales=_geyer_scales
    )
    for env, row in zip(pts, got, strict=True):
        assert row[3] == 0.0  # bottom: q_rd = 0 by construction
        assert row[6] == pytest.approx(env["q_r_lo"], rel=1e-12)  # liftoff at q_r_lo
        # Conserved angular momentum (Assumption 1): q_r^2 q_thd is the same at touchdown, bottom, liftoff.
        p_th = env["q_r_td"] ** 2 * env["q_thd_td"]
        assert row[2] ** 2 * row[5] == pytest.approx(p_th, rel=1e-12)
        assert row[6] ** 2 * row[9] == pytest.approx(p_th, rel=1e-12)


def test_geyer_stance_state_at_matches_derivation():
    pts = []
    rng = _rng("state_at")
    for env in _touchdown_points("state_at"):
        t_stance = g_geyer.geyer_stance(*(env[k] for k in STANCE_ARGS), env["q_r_lo"])[1]
        pts.append({**env, "t": rng.uniform(0.0, t_stance)})

    def ref(env, cse):
        r = _geyer_reference(env, cse)
        return r["state_at_abs_time"](r["phases"]["phase_td"] / r["env"]["omega0_hat"] + env["t"])

    _assert_agree(g_geyer.geyer_stance_state_at, ("t",) + STANCE_ARGS, pts, ref, 4)


def test_geyer_state_at_consistent_with_stance_map():
    """The trajectory kernel at t = 0, t_bottom and t_stance gives the map's touchdown, bottom, liftoff."""
    for env in _touchdown_points("consistency", n=10):
        args = [env[k] for k in STANCE_ARGS]
        res = g_geyer.geyer_stance(*args, env["q_r_lo"])
        at0 = g_geyer.geyer_stance_state_at(0.0, *args)
        at_b = g_geyer.geyer_stance_state_at(res[0], *args)
        at_lo = g_geyer.geyer_stance_state_at(res[1], *args)
        scale = [env["l0"], abs(env["q_rd_td"]), 1.0, abs(env["q_thd_td"])]
        # Touchdown: q_r and q_th exactly (the phase is built from them); q_rd is the approximate
        # (Assumption 2) radial speed, not the touchdown one, so only its sign is checked.
        assert at0[0] == pytest.approx(env["q_r_td"], rel=1e-12)
        assert at0[2] == pytest.approx(env["q_th_td"], abs=1e-12)
        assert at0[1] < 0
        assert_close(at_b[:4], res[2:6], RTOL, scale, "state_at(t_bottom) vs bottom")
        assert_close(at_lo[:4], res[6:10], RTOL, scale, "state_at(t_stance) vs liftoff")


def test_geyer_apex_return_is_composition():
    """geyer_apex_return = apex_to_touchdown, then geyer_stance, then liftoff_to_apex."""
    rng = _rng("apex_return")
    n_ok = 0
    for _ in range(40):
        env = _params(rng)
        env["q_r_td"] = env["q_r_lo"] = env["l0"] * rng.choice([1.0, rng.uniform(0.95, 1.0)])
        env["q_th_td"] = rng.uniform(0.15, 0.45)  # toe ahead of the body
        env["b_y_apex"] = env["q_r_td"] * math.cos(env["q_th_td"]) + rng.uniform(0.01, 0.2) * env["l0"]
        env["b_xd_apex"] = rng.uniform(0.5, 2.5) * math.sqrt(env["g_f"] * env["l0"])
        args = [env[k] for k in ("b_y_apex", "b_xd_apex", "q_th_td", *PARAMS, "g_f", "q_r_td", "q_r_lo")]
        got = g_geyer.geyer_apex_return(*args)
        np.testing.assert_allclose(got, g_geyer.geyer_apex_return.py_func(*args), rtol=RTOL_PYFUNC)
        td = g_flight.apex_to_touchdown(*(env[k] for k in A2T_ARGS))
        assert td[-1] == Status.OK
        st = g_geyer.geyer_stance(*td[:4], *(env[k] for k in PARAMS), env["q_r_lo"])
        if st[-1] != Status.OK:
            assert got[-1] == st[-1]
            assert all(math.isnan(x) for x in got[:-1])
            continue
        ap = g_flight.liftoff_to_apex(*st[6:10], env["g_f"])
        assert got[-1] == ap[-1]
        if ap[-1] == Status.OK:
            n_ok += 1
            expected = (ap[0], ap[1], td[4], st[1], ap[2], *st[6:10])
            np.testing.assert_allclose(got[:-1], expected, rtol=RTOL_PYFUNC)
    assert n_ok >= 10
