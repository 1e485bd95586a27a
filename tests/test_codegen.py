"""Layer 2 of CODEGEN.md: the generation pipeline and the generated modules.

- Determinism: ``build_files()`` is reproducible within a process and across processes with
  different hash seeds (set iteration order must not leak into the output).
- Drift: the committed files are what the sources produce (``slipmaps generate --check``), and a
  hand edit, an edited docs table, a missing file or a stale file is reported; ``write`` touches
  only the files that changed (numba's cache keys on modification time).
- Headers name source, template, rebuild command and pinned tool versions, no timestamp, and the
  content hashes of the generated modules a module imports; status codes are what the sources say.
- Every generated function is a numba dispatcher (no silent pure-Python fallback) and runs; every
  map of ``maps_index.MAPS`` exports its stance / state-at-time / apex-return kernels and batch
  forms with the argument orders of the index; each batch form equals its scalar form bit for bit.
- The model and flight kernels agree with ``sympy.lambdify`` of the derivations in
  ``derive/model/`` and with their own ``.py_func``; Geyer et al.'s stance kernel agrees with the
  section 3.1 derivation (eqs 7-19) evaluated step by step; every map's apex-return kernel is the
  composition flight.apex_to_touchdown -> stance -> flight.liftoff_to_apex, bit for bit.

Tolerances. A kernel and the lambdified reference evaluate the same expression arranged
differently (canonical CSE, shared reciprocals and integer powers in the kernel, SymPy's default
printing in the reference), a few dozen float64 operations each, so they differ by a few ulps times
the condition number of the expression. The sampled domain keeps that condition number small:
|q_rd_td| >= 0.3 sqrt(g l0) keeps the squared amplitude b^2 (a difference of energies) away from
cancellation, and |sin(phase)| <= 0.99 keeps asin well conditioned. Measured worst discrepancies
relative to |reference| + the output's natural magnitude (numpy 2.4, numba 0.68, sympy 1.14):
8.0e-16 kernel vs lambdify, 5.1e-16 lambdify with vs without CSE, 8.8e-16 state-at-time kernel
vs stance kernel, 0 (bit for bit) kernel vs ``.py_func``. RTOL = 1e-12 leaves three orders of
margin and still catches any wrong term, sign or branch (those are O(1) errors); RTOL_PYFUNC =
1e-14 (numba's and CPython's libm may differ by an ulp on other platforms). Near-zero outputs (a
leg angle crossing 0, the bottom rate that is 0 by construction) get an absolute floor of RTOL
times the output's natural magnitude.
"""

from __future__ import annotations

import ast
import hashlib
import importlib
import inspect
import json
import math
import os
import re
import subprocess
import sys
from functools import cache
from pathlib import Path

import kernels
import numpy as np
import pytest
import slipmaps
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st
from numba.core.registry import CPUDispatcher
from slipmaps.derive import generate
from slipmaps.derive import symbols as S
from slipmaps.derive.maps import all_maps
from slipmaps.derive.maps import geyer as d_geyer
from slipmaps.derive.model import flight as d_flight
from slipmaps.derive.model import mechanics
from slipmaps.derive.share import SUFFIX as SHARED
from slipmaps.derive.status import STATUS_CODES
from slipmaps.generated import flight as g_flight
from slipmaps.generated import geyer as g_geyer
from slipmaps.generated import maps_index
from slipmaps.generated import slip_model as g_slip
from slipmaps.generated.status import MESSAGES, Status

RTOL = 1e-12
RTOL_PYFUNC = 1e-14
N_POINTS = 20
OK = int(Status.OK)
MAPS = maps_index.MAPS
MAP_IDS = [row["name"] for row in MAPS]
MAP_MODULES = {row["name"]: importlib.import_module(f"slipmaps.generated.{row['module']}") for row in MAPS}
KERNEL_MODULES = (g_slip, g_flight, *MAP_MODULES.values())


def _mod_id(mod) -> str:
    return mod.__name__.rsplit(".", 1)[-1]


@pytest.fixture(scope="module")
def built() -> dict[str, str]:
    """Every generated file as the sources produce it (one build, about 10 s)."""
    return generate.build_files()


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


def test_build_files_deterministic_in_process(built):
    again = generate.build_files()
    assert sorted(again) == sorted(built)
    differ = [rel for rel in built if again[rel] != built[rel]]
    assert differ == [], f"a second build in the same process differs in {differ}"


@pytest.mark.slow
def test_build_files_independent_of_hash_seed(built):
    """A fresh interpreter with another PYTHONHASHSEED produces byte-identical files: set and dict
    iteration orders that depend on the seed never reach the output. One seed other than this
    process's (each costs a SymPy build, about 20 s of CPU)."""
    seed = "1" if os.environ.get("PYTHONHASHSEED") != "1" else "123"
    done = subprocess.run(
        [sys.executable, "-c", _SUBPROCESS],
        env={**os.environ, "PYTHONHASHSEED": seed},
        cwd=generate.ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == _digest(built), f"PYTHONHASHSEED={seed} gives different generated files"


def test_committed_generated_files_are_current(built):
    """What `slipmaps generate --check` runs: committed files equal the sources' output, none stale."""
    problems = generate.check(files=built)
    assert problems == [], "\n".join(problems) + "\nrun `slipmaps generate`"


@pytest.fixture
def checkout_copy(tmp_path, monkeypatch, built):
    """A checkout holding exactly the sources' output, with generate.ROOT pointed at it."""
    root = tmp_path / "checkout"
    for rel, text in built.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    (root / "pyproject.toml").write_text((generate.ROOT / "pyproject.toml").read_text())
    monkeypatch.setattr(generate, "ROOT", root)
    monkeypatch.setattr(generate, "GENERATED", root / "generated")
    return root, built


def test_check_clean_copy(checkout_copy):
    _, files = checkout_copy
    assert generate.check(files=files) == []


def test_check_detects_hand_edit(checkout_copy):
    root, files = checkout_copy
    path = root / "generated" / "geyer.py"
    text = path.read_text()
    edited = text.replace("\nNAN = math.nan\n", "\nNAN = math.nan  # tweaked\n", 1)
    assert edited != text
    path.write_text(edited)
    problems = generate.check(files=files)
    assert len(problems) == 1
    assert "a/generated/geyer.py (committed)" in problems[0]
    assert "b/generated/geyer.py (from sources)" in problems[0]
    assert "-NAN = math.nan  # tweaked\n" in problems[0]
    assert "+NAN = math.nan\n" in problems[0]


def test_check_detects_edited_docs_tables(checkout_copy):
    """docs/equations.md, docs/maps.md and the README tables between their markers are generated too."""
    root, files = checkout_copy
    eqs = root / "docs" / "equations.md"
    eqs.write_text(eqs.read_text().replace("| corrected |", "| verified |", 1))
    maps_page = root / "docs" / "maps.md"
    maps_page.write_text(maps_page.read_text().replace(MAPS[0]["title"], "A better title", 1))
    readme = root / "README.md"
    text = readme.read_text()
    begin = text.index("<!-- maps:begin")
    end = text.index("<!-- maps:end")
    row = text.index(f"{MAPS[-1]['section']}", begin)
    assert begin < row < end
    readme.write_text(text[:row] + "9.9" + text[row + len(MAPS[-1]["section"]) :])
    problems = generate.check(files=files)
    named = sorted(re.search(r"a/(\S+) \(committed\)", p).group(1) for p in problems)
    assert named == ["README.md", "docs/equations.md", "docs/maps.md"]


def test_check_detects_missing_and_stale_files(checkout_copy):
    root, files = checkout_copy
    (root / "generated" / "flight.py").unlink()
    (root / "generated" / "old_kernels.py").write_text("# left over\n")
    problems = generate.check(files=files)
    assert len(problems) == 2
    assert any("b/generated/flight.py (from sources)" in p for p in problems)
    assert any("generated/old_kernels.py: stale" in p for p in problems)


def test_generate_check_entry_point(checkout_copy, monkeypatch, capsys):
    """`slipmaps generate --check`: exit 0 when current; 1, the diff and the rebuild hint when not."""
    root, files = checkout_copy
    monkeypatch.setattr(generate, "build_files", lambda: files)
    assert generate.main(check_only=True) == 0
    assert "generated files are current" in capsys.readouterr().out
    (root / "generated" / "flight.py").write_text("# hand edit\n")
    assert generate.main(check_only=True) == 1
    out = capsys.readouterr().out
    assert "+++ b/generated/flight.py (from sources)" in out
    assert "1 generated file(s) out of date: run `slipmaps generate`." in out


def test_write_touches_only_changed_files(checkout_copy):
    """`slipmaps generate` rewrites only what changed (numba's cache keys on mtime) and drops stale files."""
    root, files = checkout_copy
    mtimes = {rel: (root / rel).stat().st_mtime_ns for rel in files}
    assert generate.write(files) == []
    assert {rel: (root / rel).stat().st_mtime_ns for rel in files} == mtimes
    (root / "generated" / "flight.py").write_text("# hand edit\n")
    (root / "generated" / "old_kernels.py").write_text("# left over\n")
    (root / "docs" / "maps.md").unlink()
    touched = generate.write(files)
    assert sorted(touched) == ["docs/maps.md", "generated/flight.py", "generated/old_kernels.py"]
    assert (root / "generated" / "flight.py").read_text() == files["generated/flight.py"]
    assert (root / "docs" / "maps.md").read_text() == files["docs/maps.md"]
    assert not (root / "generated" / "old_kernels.py").exists()
    unchanged = set(files) - {"generated/flight.py", "docs/maps.md"}
    assert all((root / rel).stat().st_mtime_ns == mtimes[rel] for rel in unchanged)
    assert generate.check(files=files) == []


# ----------------------------------------------------------------------------------------------
# Headers and status codes
# ----------------------------------------------------------------------------------------------
_TIMESTAMP = re.compile(
    r"\b\d{4}-\d{2}-\d{2}\b|\b\d{1,2}:\d{2}(:\d{2})?\b|\b(19|20)\d{2}\b|generated (on|at)\b", re.IGNORECASE
)
GENERATED_PY = sorted(f"generated/{p.name}" for p in generate.GENERATED.glob("*.py"))


def _header(text: str) -> str:
    return text.split('"""', 1)[0]


def _imports(text: str) -> set[str]:
    """The generated modules a generated module imports (``from .flight import ...``,
    ``from . import dop853``)."""
    return set(re.findall(r"^from \.(\w+) import ", text, re.MULTILINE)) | set(
        re.findall(r"^from \. import (\w+)$", text, re.MULTILINE)
    )


def _depends(text: str) -> dict[str, str]:
    """The header's dependency hashes: {file name: sha256 prefix}."""
    return dict(re.findall(r"^#\s+(\w+\.py) sha256:([0-9a-f]+)$", _header(text), re.MULTILINE))


def test_generated_py_files_are_the_built_ones(built):
    assert GENERATED_PY == sorted(rel for rel in built if rel.startswith("generated/"))


@pytest.mark.parametrize("rel", GENERATED_PY)
def test_generated_header(built, rel):
    header = _header(built[rel])
    assert "GENERATED FILE -- DO NOT EDIT" in header
    source = re.search(r"^# Source:\s+(\S+)$", header, re.MULTILINE)
    assert source, f"{rel}: header does not name its source"
    assert (generate.ROOT / source.group(1)).is_file(), source.group(1)
    template = re.search(r"^# Template:\s+(\S+)$", header, re.MULTILINE)
    assert template and (generate.ROOT / template.group(1)).is_file()
    assert re.search(r"^# Rebuild:\s+slipmaps generate\b", header, re.MULTILINE)
    assert "slipmaps generate --check" in header
    assert f"sympy {generate.VERSIONS['sympy']}, jinja2 {generate.VERSIONS['jinja2']}" in header
    assert not _TIMESTAMP.search(header), f"{rel}: header contains a timestamp-like string"


@pytest.mark.parametrize("rel", GENERATED_PY)
def test_header_hashes_every_imported_generated_module(built, rel):
    """A module that calls another's kernels records that module's content hash (numba's cache of the
    caller does not see the callee's file change otherwise). Not status.py: the codes it imports
    from there are fixed (append-only), so a cached kernel stays valid whatever else changes there
    (a message)."""
    text = built[rel]
    imports, depends = [m for m in _imports(text) if m != "status"], _depends(text)
    assert set(depends) == {f"{m}.py" for m in imports}
    for m in imports:
        assert depends[f"{m}.py"] == hashlib.sha256(built[f"generated/{m}.py"].encode()).hexdigest()[:16]


def test_generated_code_imports_only_generated_code(built):
    """Generated modules import numba, numpy, the standard library (math, collections, enum,
    inspect) and generated modules only (the exact simulator is the generator's support modules,
    generated/exact_stance.py and dop853.py, whose headers hash the generated modules they import):
    an edit of the hand-written runtime never requires a regeneration, and a regenerated equation
    of motion re-keys the exact map's caches."""
    stdlib = {"math", "collections", "enum", "inspect", "__future__"}
    allowed = {"numpy", "numba", "numba.core", "numba.extending"} | stdlib
    for rel in GENERATED_PY:
        tree = ast.parse(built[rel])
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                assert {a.name for a in node.names} <= allowed, (rel, ast.unparse(node))
            elif isinstance(node, ast.ImportFrom):
                assert node.level == 1 or node.module in allowed, (rel, ast.unparse(node))
    header = _header(built["generated/exact_stance.py"])
    deps = dict(re.findall(r"^#\s+(\w+\.py) sha256:([0-9a-f]+)$", header, re.MULTILINE))
    assert set(deps) == {"dop853.py", "slip_model.py"}, deps
    for name, digest in deps.items():
        assert digest == hashlib.sha256(built[f"generated/{name}"].encode()).hexdigest()[:16], name
    assert "exact_stance.py" in _depends(built["generated/exact.py"])


def test_map_modules_depend_on_flight_and_geyer(built):
    """geyer imports flight (apex return) and the generator's support module (stack arrays for the
    role kernels' calls); flight imports the support module only (its checks, support.all_finite),
    the equations of motion nothing; every gravity map also imports geyer (section 4 builds on
    3.1)."""
    assert set(_depends(built["generated/geyer.py"])) == {"flight.py", "support.py"}
    assert set(_depends(built["generated/flight.py"])) == {"support.py"}
    assert not _depends(built["generated/slip_model.py"])
    gravity = [row for row in MAPS if row["name"].startswith("gravity-")]
    assert len(gravity) >= 6
    for row in gravity:
        assert {"flight.py", "geyer.py"} <= set(_depends(built[f"generated/{row['module']}.py"])), row["name"]


def test_pinned_tool_versions_used():
    """The header's tool versions must be the pinned ones, or the drift check compares noise."""
    pyproject = (generate.ROOT / "pyproject.toml").read_text()
    for tool in ("sympy", "jinja2"):
        pins = set(re.findall(rf'"{tool}==([0-9.]+)"', pyproject))
        assert pins == {generate.VERSIONS[tool]}, tool
    assert generate.VERSIONS["sympy"] == sp.__version__


def test_no_generated_line_is_longer_than_the_limit(built):
    """The limit the templates state (derive/wrap.py, the project's line length): every generated
    Python line, code, comments and docstrings, is at most 110 characters."""
    from slipmaps.derive.wrap import LIMIT

    assert LIMIT == 110
    for rel, text in built.items():
        if rel.endswith(".py"):
            long = [(i + 1, len(ln)) for i, ln in enumerate(text.splitlines()) if len(ln) > LIMIT]
            assert not long, (rel, long[:5])


def test_no_generated_module_is_longer_than_3000_lines(built):
    """Issue 29's bound on a generated module (a reviewer reads its diff): at most 3,000 lines; the
    largest, iterative_jacobian.py, has 2,714 today."""
    sizes = {rel: text.count("\n") for rel, text in built.items() if rel.endswith(".py")}
    assert len(sizes) > 20, sorted(sizes)
    assert max(sizes.values()) <= 3000, max(sizes.items(), key=lambda kv: kv[1])


def _without_docstrings(source: str) -> str:
    import ast

    tree = ast.parse(source)
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list) and body and isinstance(body[0], ast.Expr):
            if isinstance(body[0].value, ast.Constant) and isinstance(body[0].value.value, str):
                body[0].value.value = ""
    return ast.dump(tree)


def test_line_breaking_keeps_the_code():
    """derive/wrap.py breaks lines between tokens inside brackets (or puts a right-hand side in
    parentheses): the statements' syntax trees are unchanged, the result is its own fixed point."""
    from slipmaps.derive.wrap import wrap

    terms = " + ".join(f"{i}.5*_x{i}*math.sqrt(q_r_td)" for i in range(40))
    source = "\n".join(
        [
            "from .status import " + ", ".join(f"STATUS_NAME_{i}" for i in range(20)),
            "",
            "",
            "def f(" + ", ".join(f"argument_{i}" for i in range(30)) + "):",
            '    """' + " ".join(["word"] * 60) + "',",
            "",
            "    Returns a tuple:",
            "        name: " + " ".join(["text"] * 50),
            '    """',
            "    # " + " ".join(["comment"] * 30),
            f"    y = {terms}",
            f"    if not (math.isfinite(y) and {terms} > 0.0):",
            "        return _NAN3 + (STATUS_FALL,)",
            "    (" + ", ".join(f"a{i}" for i in range(40)) + ", _) = _c0",
            "    return (" + ", ".join(f"a{i}" for i in range(40)) + ", STATUS_OK)",
            "",
        ]
    )
    out = wrap(source)
    assert max(map(len, out.splitlines())) <= 110
    assert _without_docstrings(out) == _without_docstrings(source)
    assert wrap(out) == out
    assert len(out.splitlines()) < 2 * len(source) / 110 + len(source.splitlines())


_PLAIN = st.recursive(
    st.none()
    | st.booleans()
    | st.integers()
    | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(max_size=300),
    lambda inner: (
        st.lists(inner, max_size=8)
        | st.dictionaries(st.text(max_size=20), inner, max_size=8)
        | st.tuples(inner, inner)
    ),
    max_leaves=60,
)


@given(value=_PLAIN, first=st.integers(0, 40))
def test_dense_reads_back_within_the_limit(value, first):
    """derive/wrap.py's dense(): the generated index's data packed into lines that read back as the
    same value, none longer than the limit (the first after ``first`` characters of its statement)."""
    import ast

    from slipmaps.derive.wrap import LIMIT, dense

    out = dense(value, first=first)
    assert ast.literal_eval(out) == value
    lines = out.split("\n")
    assert len(lines[0]) + first <= LIMIT
    assert all(len(ln) <= LIMIT for ln in lines[1:])


@given(
    tables=st.dictionaries(st.from_regex(r"[A-Z]{1,6}", fullmatch=True), _PLAIN, max_size=5),
    least=st.integers(1, 40),
)
def test_intern_repeats_reads_back_as_the_tables(tables, least):
    """derive/wrap.py's intern_repeats(): the tables rendered with every repeated list or dict written
    once execute back to the same tables; each constant is defined before its first use and named
    at least twice besides; a value repeated with ``least`` characters or more gets a constant or
    is a table the others name."""
    from slipmaps.derive.wrap import dense, intern_repeats

    out = intern_repeats(tables, least=least)
    assert [n for n, _ in out if not n.startswith("_repeated")] == list(tables)
    # (in brackets: a bare long string packs into adjacent literals on several lines)
    source = "\n".join(f"{n} = ({dense(v, first=len(n) + 4)})" for n, v in out)
    namespace: dict = {}
    exec(source, namespace)  # NameError unless every constant is defined before its use
    assert {n: namespace[n] for n in tables} == tables
    constants = [n for n, _ in out if n.startswith("_repeated")]
    for n in constants:
        assert len(re.findall(rf"\b{n}\b", source)) >= 3, n
    reprs = [r for v in tables.values() for r in _nested_reprs(v)]
    repeated = {r for r in reprs if reprs.count(r) > 1 and len(r) >= least}
    if repeated:
        assert constants or any(repr(v) in repeated for v in tables.values())


def _nested_reprs(value):
    if isinstance(value, (list, dict)):
        yield repr(value)
        for child in value.values() if isinstance(value, dict) else value:
            yield from _nested_reprs(child)


def test_index_writes_a_repeated_layout_once():
    """The gravity family's members share their stance outputs (the stance's and the extras): one
    object in the index."""
    rows = [r for r in MAPS if r["name"].startswith("gravity-type") and r["fixed"]]
    assert len(rows) == 5
    assert all(r["kernels"]["stance"]["out"] is rows[0]["kernels"]["stance"]["out"] for r in rows)


def test_docs_table_header(built):
    for rel in ("docs/equations.md", "docs/maps.md"):
        first = built[rel].splitlines()[0]
        assert first.startswith("<!-- GENERATED by `slipmaps generate`"), rel
        assert not _TIMESTAMP.search(first)


def test_status_enum_matches_source():
    assert [(st.name, st.value) for st in Status] == [(n, c) for n, c, _ in STATUS_CODES]
    assert MESSAGES == {c: msg for _, c, msg in STATUS_CODES}
    codes = [c for _, c, _ in STATUS_CODES]
    assert codes == list(range(len(codes))), "codes are append-only and consecutive"
    assert STATUS_CODES[0][:2] == ("OK", 0)


@pytest.mark.parametrize("name", sorted(generate.OWN_MODULES))
def test_a_kernel_module_named_like_the_packages_own_is_refused(name):
    """A declared map named ``rows`` (say) would overwrite generated/rows.py: refused at generation."""
    from slipmaps.derive.ir import Module

    kept = Module(name="geyer", doc="", source="", kernels=tuple)
    generate.check_module_names([kept])
    with pytest.raises(ValueError, match=rf"\['{name}'\].*generated package's own modules"):
        generate.check_module_names([kept, Module(name=name, doc="", source="", kernels=tuple)])


def _all_kernel_modules():
    """Every generated kernel module (the maps', the model's and the Jacobians')."""
    names = sorted(p.stem for p in (generate.ROOT / "generated").glob("*.py"))
    skip = {"__init__", "status", "maps_index"}
    return [importlib.import_module(f"slipmaps.generated.{n}") for n in names if n not in skip]


@pytest.mark.parametrize("mod", _all_kernel_modules(), ids=_mod_id)
def test_module_status_constants_come_from_status_py(mod):
    """The status codes a module names are imported from generated/status.py (one definition, the
    values of derive/status.py), not copied into it."""
    from slipmaps.generated import status

    text = Path(mod.__file__).read_text()
    assert not re.search(r"^STATUS_\w+ =", text, re.MULTILINE), "a status constant defined in the module"
    used = set(re.findall(r"\bSTATUS_(\w+)\b", text))
    consts = {n[len("STATUS_") :]: v for n, v in vars(mod).items() if n.startswith("STATUS_")}
    assert set(consts) == used
    codes = {n: c for n, c, _ in STATUS_CODES}
    assert consts == {n: codes[n] for n in consts}
    assert all(getattr(status, f"STATUS_{n}") == c for n, c in codes.items())
    if consts:
        assert re.search(r"^from \.status import", text, re.MULTILINE)


# ----------------------------------------------------------------------------------------------
# Every map's module and kernels; every function a dispatcher that runs; batch == scalar
# ----------------------------------------------------------------------------------------------
#: An in-domain value for each argument name of the model, flight and map kernels (a human runner:
#: every stance, state-at-time and apex-return kernel returns OK here).
NOMINAL = {
    "q_r": 0.95,
    "q_rd": -0.5,
    "q_th": 0.3,
    "q_thd": -3.0,
    "m": 80.0,
    "l0": 1.0,
    "k": 20_000.0,
    "k_c": 20_000.0,
    "k_d": 20_000.0,
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
    "ground": 0.0,
    "direction": 1.0,
    "rtol": 1e-11,
    "atol": 1e-12,
}


def option_defaults(row: dict) -> dict[str, float]:
    """Each option's default as the kernel receives it (a choice as the index of its value), and
    what a family member fixes."""
    out = dict(row["fixed"])
    for opt in row["options"]:
        if opt["kind"] == "choice":
            out[opt["name"]] = float([ch["value"] for ch in opt["choices"]].index(opt["default"]))
        else:
            out[opt["name"]] = float(opt["default"])
    return out


def _params(fn) -> list[str]:
    return list(inspect.signature(fn.py_func).parameters)


def _is_kernel(mod, obj) -> bool:
    return isinstance(obj, CPUDispatcher) and obj.py_func.__module__ == mod.__name__


def _own_kernels(mod) -> list[str]:
    return [n for n, obj in vars(mod).items() if _is_kernel(mod, obj)]


def test_index_lists_every_declared_map():
    assert MAP_IDS == [spec.name for spec in all_maps()]
    assert len(set(MAP_IDS)) == len(MAP_IDS)


def test_a_map_is_declared_in_the_module_named_after_it_or_its_family():
    """derive/maps/<name>.py declares the map <name> (or, a family module, the maps <name>-...): the
    check all_maps() runs names the module a misplaced declaration belongs in; a module that declares
    no map is named *_helpers.py."""
    from slipmaps.derive import maps

    specs = {spec.name: spec for spec in all_maps()}
    maps._check_layout([("geyer", specs["geyer"]), ("gravity", specs["gravity-type2"])], "map")
    with pytest.raises(
        ValueError, match=r"geyer-vs is declared in derive/maps/geyer\.py: it belongs in .*/geyer_vs\.py"
    ):
        maps._check_layout([("geyer", specs["geyer-vs"])], "map")
    with pytest.raises(ValueError, match=r"gravity-type5 .* belongs in derive/maps/gravity_type5\.py"):
        maps._check_layout([("gravity", specs["gravity-type5"])], "map")
    # derive/maps/<module>.py of every declaration
    sources = {spec.source for spec in (*all_maps(), *maps.all_halves(), maps.ground_truth())}
    modules = [m.__name__.rsplit(".", 1)[-1] for m in maps._modules()]
    assert any(m.endswith(maps.HELPERS_SUFFIX) for m in modules)
    for m in modules:
        assert (f"derive/maps/{m}.py" in sources) != m.endswith(maps.HELPERS_SUFFIX), m


@pytest.mark.parametrize("row", [*MAPS, maps_index.EXACT], ids=[*MAP_IDS, "exact"])
def test_map_module_exports_kernels_with_index_signatures(row):
    """The index publishes every role kernel's layouts (what the runtime fills by name): each role's
    function exists in its module, jitted, as ``kernel(x, p, out)``, with its batch form
    ``kernel_rows(X, P, OUT, STATUS)``; the inputs x are the role's (the touchdown state, the apex,
    t and the touchdown state), the parameter record p the map's parameters, the flights' and its
    kernel options, the same for every role."""
    roles = row["kernels"]
    assert {"stance", "apex_return", "stance_jacobian", "apex_return_jacobian"} <= set(roles)
    for role, spec in roles.items():
        mod = importlib.import_module(f"slipmaps.generated.{spec['module']}")
        for fn_name, fn_args in (
            (spec["name"], ["x", "p", "out"]),
            (f"{spec['name']}_rows", ["X", "P", "OUT", "STATUS"]),
        ):
            fn = getattr(mod, fn_name, None)
            assert fn is not None, f"{mod.__name__} has no {fn_name}"
            assert _is_kernel(mod, fn), fn_name
            assert _params(fn) == fn_args, fn_name
        assert spec["p"] == roles["stance"]["p"], role
    assert roles["stance"]["x"] == maps_index.TOUCHDOWN
    # a family member's record holds the family's options: its own and those it fixes (row "fixed")
    fixed = row["fixed"]
    params = [p for p in roles["stance"]["p"] if not any(o["name"] == p for o in row["options"])]
    params = [p for p in params if p not in fixed]
    assert set(row["params"]) <= set(params) and {"g_f", "q_r_td", "q_r_lo"} <= set(params)
    options = [o["name"] for o in row["options"] if o["kernel"]]
    assert [p for p in roles["stance"]["p"][len(params) :] if p not in fixed] == options
    assert set(roles["stance"]["p"][len(params) :]) == set(options) | set(fixed)
    assert roles["apex_return"]["x"] == list(maps_index.APEX_PUBLIC)
    if "state_at" in roles:
        assert roles["state_at"]["x"] == ["t", *maps_index.TOUCHDOWN]
    assert roles["apex_return_jacobian"]["wrt"][: len(maps_index.APEX_PUBLIC)] == list(maps_index.APEX_PUBLIC)


@pytest.mark.parametrize("mod", KERNEL_MODULES, ids=_mod_id)
def test_no_pure_python_functions(mod):
    """Every function a generated module defines is jitted: no silent fallback to Python."""
    plain = [n for n, o in vars(mod).items() if inspect.isfunction(o) and o.__module__ == mod.__name__]
    assert plain == []
    assert _own_kernels(mod)
    # The options CODEGEN.md asks for, stated in the source: cached, no fastmath (NaN/inf semantics).
    text = Path(mod.__file__).read_text()
    defs = re.findall(r"^def (\w+)", text, re.MULTILINE)
    decorated = dict((n, d) for d, n in re.findall(r"^@(.*)\ndef (\w+)", text, re.MULTILINE))
    assert sorted(defs) == sorted(decorated) == sorted(_own_kernels(mod))
    for name, deco in decorated.items():
        assert deco.startswith("njit(cache=True") and "fastmath" not in deco, (name, deco)


def _nominal_args(mod, kernel) -> dict[str, float]:
    row = next((r for r in MAPS if MAP_MODULES[r["name"]] is mod), None)
    env = {**NOMINAL, **(option_defaults(row) if row else {})}
    # Helper kernels take internal quantities (phases, amplitudes ...): any moderate value runs.
    return {a: env.get(a, 0.5) for a in kernel.arg_names}


def _scalar_kernels():
    out = []
    for mod in KERNEL_MODULES:
        for name in _own_kernels(mod):
            # (a shared body runs through its entry points: tests/test_share.py)
            if not name.endswith(("_rows", SHARED)):
                out.append(pytest.param(mod, name, id=f"{_mod_id(mod)}.{name}"))
    return out


def _map_kernel_names() -> set[str]:
    return {k["name"] for row in MAPS for role, k in row["kernels"].items() if not role.endswith("_jacobian")}


@pytest.mark.parametrize(("mod", "name"), _scalar_kernels())
def test_kernel_is_dispatcher_and_runs(mod, name):
    kern = getattr(mod, name)
    declared = kernels.declaration(mod.__name__, name)
    res = kernels.invoke(declared, _nominal_args(mod, declared))
    res = res if isinstance(res, tuple) else (res,)
    if isinstance(res[-1], int):  # a status code: OK and finite outputs, or another code and NaNs
        assert res[-1] in MESSAGES
        vals = res[:-1]
        assert all(math.isfinite(v) for v in vals) if res[-1] == OK else all(math.isnan(v) for v in vals)
        if name in _map_kernel_names() or mod is g_flight:
            assert res[-1] == OK, res
    else:
        assert all(isinstance(v, float) and math.isfinite(v) for v in res), res
    assert kern.signatures, "compiled"


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


def _params_sample(rng):
    m = rng.uniform(2.0, 100.0)
    l0 = rng.uniform(0.25, 1.2)
    g_s = rng.uniform(9.0, 10.0)
    k = rng.uniform(10.0, 40.0) * m * g_s / l0  # dimensionless stiffness 10-40
    # c: a lossless leg (the maps that take the leg damping read it; tests/test_iterative_damped.py)
    return {"m": m, "l0": l0, "k": k, "k_c": k, "k_d": k, "g_s": g_s, "g_f": rng.uniform(9.0, 10.0), "c": 0.0}


def _geyer(name: str, env) -> tuple:
    """A kernel of module geyer at the arguments ``env`` (by name): outputs, status."""
    return kernels.invoke(kernels.declaration("geyer", name), env)


def _assert_agree(kernel, args_names, points, reference, n_out, rtol=RTOL, scales=None):
    """kernel(*args) vs kernel.py_func(*args) vs reference(env, cse) for cse in (False, True).

    ``scales(env)`` gives each output's natural magnitude (for outputs that are 0 by construction);
    by default the largest |reference| of the output over the sample.
    """
    got, py, ref, ref_cse = [], [], [], []
    declared = kernels.declaration(kernel.py_func.__module__, kernel.__name__)
    assert declared.arg_names == tuple(args_names)
    for env in points:
        r = kernels.invoke(declared, env)
        got.append(r if isinstance(r, tuple) else (r,))
        r = kernels.invoke(declared, env, kernel.py_func)
        py.append(r if isinstance(r, tuple) else (r,))
        ref.append(reference(env, False))
        ref_cse.append(reference(env, True))
    got, py = np.array(got, dtype=float), np.array(py, dtype=float)
    ref, ref_cse = np.array(ref, dtype=float), np.array(ref_cse, dtype=float)
    assert got.shape[1] in (n_out, n_out + 1)
    if got.shape[1] == n_out + 1:  # status column
        assert (got[:, -1] == OK).all(), got[:, -1]
        assert (py[:, -1] == OK).all()
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
        p = _params_sample(rng)
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


def test_eq1_3_stance_polar_rhs_matches_derivation():
    exprs = mechanics.stance_polar_rhs()
    _assert_agree(
        g_slip.stance_polar_rhs,
        POLAR + PARAMS,
        _polar_points("polar_rhs"),
        lambda env, cse: [ev(e, env, cse) for e in exprs],
        4,
    )


SENS = ("s_q_r", "s_q_rd", "s_q_th", "s_q_thd", "s_k")


def test_eq2_3_stance_polar_tangent_is_the_fields_derivative():
    """The variational field of the exact Jacobian (generated/exact_stance.py): J s + f_k s_k from
    the derivation, and the directional derivative of the generated field by central differences
    (h = 1e-6 of the direction; the quotient's error O(h^2) and round-off / h: measured 6.1e-11 of
    |quotient| + the field's scale at most, bound 1e-9)."""
    rhs = sp.Matrix(mechanics.stance_polar_rhs())
    column = sp.Matrix([sp.Symbol(n) for n in SENS[:4]])
    tangent = rhs.jacobian([S.q_r, S.q_rd, S.q_th, S.q_thd]) * column + sp.diff(rhs, S.k) * sp.Symbol("s_k")
    exprs = list(tangent)
    rng = _rng("polar_tangent")
    pts = _polar_points("polar_tangent")
    for env in pts:
        env.update(zip(SENS[:4], rng.normal(size=4), strict=True))
        env["s_k"] = float(rng.integers(0, 2)) * rng.uniform(0.5, 2.0)
    got = _assert_agree(
        g_slip.stance_polar_tangent,
        POLAR + SENS + PARAMS,
        pts,
        lambda env, cse: [ev(e, env, cse) for e in exprs],
        4,
    )
    h = 1e-6
    for env, tangent in zip(pts, got, strict=True):

        def field(sign, env=env):
            y = [env[n] + sign * h * env[f"s_{n}"] for n in POLAR]
            k = env["k"] + sign * h * env["s_k"]
            return np.array(g_slip.stance_polar_rhs(*y, env["m"], env["l0"], k, env["g_s"]))

        quotient = (field(1.0) - field(-1.0)) / (2 * h)
        # the field's natural magnitudes: the spring's and gravity's accelerations, and 10 for the
        # rates and the centripetal and Coriolis terms (|q_rd| <= 3 m/s, |q_thd| <= 6 rad/s)
        scale = env["k"] / env["m"] * env["l0"] + env["g_s"] + 10.0
        assert_close(tangent, quotient, 1e-9, scale, "tangent vs central differences")


def test_stance_cartesian_rhs_matches_derivation_and_polar_field():
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


def test_eq27_stance_energy_matches_derivation():
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
        p = _params_sample(rng)
        q_th_td = rng.uniform(-0.6, 0.6)
        q_r_td = rng.uniform(0.8, 1.0) * p["l0"]
        ground = rng.uniform(-0.2, 0.2) * p["l0"]  # a step up (> 0) or down
        p.update(
            q_th_td=q_th_td,
            q_r_td=q_r_td,
            ground=ground,
            b_y_apex=max(ground, 0.0) + q_r_td * math.cos(q_th_td) + rng.uniform(0.02, 0.5) * p["l0"],
            b_xd_apex=rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 8.0),  # signed: either direction
        )
        # a swinging leg, within the concave range and short of the horizontal at touchdown
        t_far = math.sqrt(2 * (p["b_y_apex"] - ground + q_r_td) / p["g_f"])
        bound = min(0.9 * math.sqrt(p["g_f"] / q_r_td), (1.4 - abs(q_th_td)) / t_far)
        p["retraction_rate"] = rng.uniform(-1.0, 1.0) * bound
        pts.append(p)
    return pts


A2T_ARGS = ("b_y_apex", "b_xd_apex", "q_th_td", "q_r_td", "g_f", "ground", "retraction_rate")


def _apex_to_touchdown_ref(env, cse):
    """The derivation's touchdown: its closed-form start, Newton's method on its residual to round-off
    (here, in floats), then its state and foot at that time."""
    atd = d_flight.apex_to_touchdown()
    env = {**env, atd["drop_symbol"].name: ev(atd["drop"], env, cse)}
    env[atd["t0_symbol"].name] = t = ev(atd["t0"], env, cse)
    for _ in range(60):
        step = ev(atd["residual"], {**env, "t": t}, cse) / ev(atd["slope"], {**env, "t": t}, cse)
        t -= step
        if abs(step) <= 1e-15 * t:
            break
    env = {**env, "t": t, atd["angle_symbol"].name: ev(atd["angle"], {**env, "t": t}, cse)}
    return [ev(e, env, cse) for e in atd["state"]] + [t, ev(atd["foot_x"], env, cse)]


def test_apex_to_touchdown_matches_derivation():
    assert _params(g_flight.apex_to_touchdown) == list(A2T_ARGS)
    pts = _apex_points("a2t")
    got = _assert_agree(g_flight.apex_to_touchdown, A2T_ARGS, pts, _apex_to_touchdown_ref, 6)
    # Physics of the descent onto ground `ground` higher with the leg swinging at retraction_rate:
    # at touchdown the foot is on the ground, the leg at the swung angle, the falling speed g t, the
    # horizontal speed kept, the toe a flight's travel plus q_r_td sin(angle) ahead of the apex.
    assert any(abs(env["retraction_rate"]) > 0.1 for env in pts)
    for env, row in zip(pts, got, strict=True):
        t = row[4]
        angle = env["q_th_td"] + env["retraction_rate"] * t
        assert row[2] == pytest.approx(angle, rel=1e-12, abs=1e-14)
        foot_y = env["b_y_apex"] - env["g_f"] * t * t / 2 - env["ground"] - env["q_r_td"] * math.cos(angle)
        assert abs(foot_y) <= 1e-12 * env["l0"], foot_y
        _, xd, _, yd = g_slip.polar_to_cartesian(*row[:4])
        assert xd == pytest.approx(env["b_xd_apex"], rel=1e-12)
        assert yd == pytest.approx(-env["g_f"] * t, rel=1e-12)
        foot = env["b_xd_apex"] * t + env["q_r_td"] * math.sin(angle)
        assert row[5] == pytest.approx(foot, rel=1e-12, abs=1e-12)


def _liftoff_points(name, n=N_POINTS):
    """Liftoff states moving up and forward (the domain where liftoff_to_apex returns OK)."""
    rng = _rng(name)
    pts = []
    while len(pts) < n:
        p = _params_sample(rng)
        p.update(
            q_r=rng.uniform(0.8, 1.0) * p["l0"],
            q_rd=rng.uniform(0.2, 3.0),
            q_th=rng.uniform(-0.6, -0.05),
            q_thd=rng.uniform(-6.0, -0.5),
        )
        p["direction"] = 1.0
        if g_flight.liftoff_to_apex(*(p[n] for n in POLAR), p["g_f"], p["direction"])[-1] == OK:
            pts.append(p)
    return pts


def _liftoff_to_apex_ref(env, cse):
    lta = d_flight.liftoff_to_apex()
    env = {**env, **{n: ev(e, env, cse) for n, e in zip(CART, lta["liftoff_cartesian"], strict=True)}}
    return [ev(lta[key], env, cse) for key in ("b_y_apex", "b_xd_apex", "t_flight", "dx_flight", "apex_b_x")]


def test_liftoff_to_apex_matches_derivation():
    pts = _liftoff_points("l2a")
    got = _assert_agree(g_flight.liftoff_to_apex, POLAR + ("g_f", "direction"), pts, _liftoff_to_apex_ref, 5)
    for env, row in zip(pts, got, strict=True):
        x, xd, y, yd = g_slip.polar_to_cartesian(*(env[n] for n in POLAR))
        # Energy per unit mass is conserved in flight: g y + yd^2 / 2 = g * apex height.
        assert row[0] * env["g_f"] == pytest.approx(env["g_f"] * y + yd**2 / 2, rel=1e-12)
        assert row[3] == pytest.approx(xd * row[2], rel=1e-12)
        assert row[4] == pytest.approx(x + row[3], rel=1e-12)  # the next apex relative to the toe


def test_liftoff_against_the_direction_is_backward_and_a_hop_in_place_goes_either_way():
    """LIFTOFF_BACKWARD is relative to the step's direction (the sign of its apex speed): the same
    liftoff moving toward +x is backward for a step toward -x, and fine for a hop in place."""
    forward = (1.0, 1.5, -0.3, -4.4)
    ok, backward, either = (g_flight.liftoff_to_apex(*forward, 9.81, d)[-1] for d in (1.0, -1.0, 0.0))
    assert ok == OK and backward == int(Status.LIFTOFF_BACKWARD) and either == OK


# Geyer et al.'s stance map (report section 3.1) ------------------------------------------------
STANCE_ARGS = ("q_r_td", "q_rd_td", "q_th_td", "q_thd_td") + PARAMS + ("q_r_lo",)


def _touchdown_points(name, n=N_POINTS):
    """Random touchdown states (compressing, human/robot scales) where geyer_stance returns OK."""
    rng = _rng(name)
    pts = []
    while len(pts) < n:
        p = _params_sample(rng)
        l0 = p["l0"]
        p.update(
            q_r_td=l0 * rng.choice([1.0, rng.uniform(0.93, 1.0)]),
            q_rd_td=-rng.uniform(0.3, 2.5) * math.sqrt(p["g_s"] * l0),
            q_th_td=rng.uniform(-0.5, 0.5),
            q_thd_td=-rng.uniform(0.5, 2.0) * math.sqrt(p["g_s"] / l0),
            q_r_lo=l0 * rng.choice([1.0, rng.uniform(0.93, 1.0)]),
        )
        if _geyer("geyer_stance", p)[-1] == OK:
            if _geyer_reference(p, False)["max_abs_s"] <= 0.99:
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


def test_eq7_19_geyer_stance_matches_section_3_1_derivation():
    pts = _touchdown_points("geyer")
    got = _assert_agree(g_geyer.geyer_stance, STANCE_ARGS, pts, _geyer_stance_ref, 10, scales=_geyer_scales)
    for env, row in zip(pts, got, strict=True):
        assert row[3] == 0.0  # bottom: q_rd = 0 by construction, eq (13)
        assert row[6] == env["q_r_lo"]  # liftoff at q_r_lo, eq (14)
        # Conserved angular momentum (Assumption 1): q_r^2 q_thd is the same at touchdown, bottom, liftoff.
        p_th = env["q_r_td"] ** 2 * env["q_thd_td"]
        assert row[2] ** 2 * row[5] == pytest.approx(p_th, rel=1e-12)
        assert row[6] ** 2 * row[9] == pytest.approx(p_th, rel=1e-12)


def test_eq11_17_19_geyer_state_at_matches_derivation():
    pts = []
    rng = _rng("state_at")
    for env in _touchdown_points("state_at"):
        t_stance = _geyer("geyer_stance", env)[1]
        pts.append({**env, "t": rng.uniform(0.0, t_stance)})

    def ref(env, cse):
        r = _geyer_reference(env, cse)
        return r["state_at_abs_time"](r["phases"]["phase_td"] / r["env"]["omega0_hat"] + env["t"])

    scales = lambda env: [env["l0"], abs(env["q_rd_td"]), 1.0, abs(env["q_thd_td"])]  # noqa: E731
    _assert_agree(g_geyer.geyer_state_at, ("t",) + STANCE_ARGS, pts, ref, 4, scales=scales)


def test_geyer_state_at_reproduces_stance_outputs():
    """The trajectory kernel at t = 0, t_bottom and t_stance gives the map's touchdown, bottom, liftoff."""
    for env in _touchdown_points("consistency", n=10):
        res = _geyer("geyer_stance", env)
        at0 = _geyer("geyer_state_at", {**env, "t": 0.0})
        at_b = _geyer("geyer_state_at", {**env, "t": res[0]})
        at_lo = _geyer("geyer_state_at", {**env, "t": res[1]})
        assert at0[-1] == at_b[-1] == at_lo[-1] == OK
        scale = [env["l0"], abs(env["q_rd_td"]), 1.0, abs(env["q_thd_td"])]
        # Touchdown: q_r and q_th exactly (the phase is built from them); q_rd is the approximate
        # (Assumption 2) radial speed, not the touchdown one, so only its sign is checked.
        assert at0[0] == pytest.approx(env["q_r_td"], rel=1e-12)
        assert at0[2] == pytest.approx(env["q_th_td"], abs=1e-12)
        assert at0[1] < 0
        assert_close(at_b[:4], res[2:6], RTOL, scale, "state_at(t_bottom) vs bottom")
        assert_close(at_lo[:4], res[6:10], RTOL, scale, "state_at(t_stance) vs liftoff")


# Every map: apex return = exact descent, the map's stance, exact ascent ------------------------
STANCE_OUT = [r["name"] for r in maps_index.STANCE_OUTPUTS]
APEX_OUT = [r["name"] for r in maps_index.APEX_OUTPUTS]


@pytest.mark.parametrize("row", MAPS, ids=MAP_IDS)
def test_apex_return_is_flight_stance_flight_composition(row):
    """<map>_apex_return = flight.apex_to_touchdown -> <map>_stance -> flight.liftoff_to_apex, bit for bit,
    with the map's default options; a failing stage's status is the kernel's status."""
    spec_ap, spec_st = row["kernels"]["apex_return"], row["kernels"]["stance"]
    apex_return = kernels.declaration(spec_ap["module"], spec_ap["name"])
    stance = kernels.declaration(spec_st["module"], spec_st["name"])
    extras = [e["name"] for e in row["extras"]]
    stance_names = STANCE_OUT + extras
    opts = option_defaults(row)
    rng = _rng(f"apex_return {row['name']}")
    n_ok = n_fail = 0
    for _ in range(30):
        env = {**_params_sample(rng), **opts}
        env["q_r_td"] = env["l0"] * rng.choice([1.0, rng.uniform(0.95, 1.0)])
        env["q_r_lo"] = env["l0"] * rng.choice([1.0, rng.uniform(0.95, 1.0)])
        env["q_th_td"] = rng.uniform(0.1, 0.45)  # toe ahead of the body
        env["ground"] = rng.uniform(-0.1, 0.1) * env["l0"]
        env["b_y_apex"] = (
            env["ground"] + env["q_r_td"] * math.cos(env["q_th_td"]) + rng.uniform(-0.01, 0.2) * env["l0"]
        )
        env["b_xd_apex"] = rng.uniform(0.3, 2.5) * math.sqrt(env["g_f"] * env["l0"])
        env["retraction_rate"] = rng.choice([0.0, rng.uniform(-1.0, 0.3)])
        got = kernels.invoke(apex_return, env)
        assert len(got) == len(APEX_OUT) + len(extras) + 1
        td = kernels.invoke(kernels.declaration("flight", "apex_to_touchdown"), env)
        stance_env = {**env, **dict(zip(maps_index.TOUCHDOWN, td[:4], strict=True))}
        st = kernels.invoke(stance, stance_env)
        failed = next((res[-1] for res in (td, st) if res[-1] != OK), None)
        if failed is None:
            out = dict(zip(stance_names, st[:-1], strict=True))
            ap = g_flight.liftoff_to_apex(*(out[f"liftoff_{p}"] for p in POLAR), env["g_f"], 1.0)
            failed = None if ap[-1] == OK else ap[-1]
        if failed is not None:
            n_fail += 1
            assert got[-1] == failed
            assert all(math.isnan(v) for v in got[:-1])
            continue
        n_ok += 1
        expected = {
            "apex_height": ap[0],
            "apex_speed": ap[1],
            "t_descent": td[4],
            "t_ascent": ap[2],
            "step_length": td[5] + ap[4],
            "foot_x": td[5],
            "foot_y": env["ground"] - env["b_y_apex"],
            "touchdown_q_th": td[2],
            **{k: out[k] for k in ("t_stance", *(f"liftoff_{p}" for p in POLAR), *extras)},
        }
        assert got == (*(expected[k] for k in APEX_OUT + extras), OK)
    assert n_ok >= 10 and n_fail >= 1, (n_ok, n_fail)


#: The batch forms run with a parameter record per row: every map's stance, and the apex return and
#: its Jacobian of the maps whose Jacobians benchmarks/ compare (the compile time of the others').
_PER_ROW = [
    *((name, "stance") for name in MAP_IDS),
    *(
        (name, role)
        for name in ("geyer", "iterative-report")
        for role in ("apex_return", "apex_return_jacobian")
    ),
]


@pytest.mark.parametrize(("name", "role"), _PER_ROW, ids=[f"{n}-{r}" for n, r in _PER_ROW])
def test_a_batch_form_gives_each_row_its_own_parameter_record(name, role):
    """A batch form ``<kernel>_rows(X, P, OUT, STATUS)`` runs the rows of each parameter record with
    a copy of the record on its stack (derive/templates/kernels.py.j2). With a record per row (a
    plant's stiffness per run, runtime/control/plant.py), each row is what the same row gives run
    alone with its record, bit for bit, statuses included; with two records for five rows the
    second serves rows 1-4; the rows of one shared record are those of the record per row."""
    from slipmaps.runtime.api.calls import Call, kernel_functions

    call = Call.of(name, slipmaps.HUMAN_RUNNER, {})
    spec = call.spec(role)
    rows = kernel_functions(spec)[1]
    rng = _rng(f"per row {name} {role}")
    n = 24
    if role == "stance":
        X = np.column_stack(
            [
                np.full(n, slipmaps.HUMAN_RUNNER.q_r_td),
                rng.uniform(-2.0, -1.0, n),
                rng.uniform(0.25, 0.4, n),
                rng.uniform(-5.5, -3.5, n),
            ]
        )
    else:
        X = np.zeros((n, len(spec.x)))
        for j, a in enumerate(spec.x):
            X[:, j] = {"b_y_apex": rng.uniform(1.0, 1.1, n), "b_xd_apex": rng.uniform(3.0, 7.0, n)}.get(
                a, rng.uniform(0.3, 0.5, n) if a == "q_th_td" else 0.0
            )
    P = np.repeat(call.record(spec)[None, :], n, axis=0)
    stiff = [j for j, f in enumerate(spec.p) if f in ("k", "k_c", "k_d")]
    assert stiff, spec.p
    for j in stiff:
        P[:, j] *= rng.uniform(0.8, 1.25, n)

    def run(X, P):
        out, status = np.empty((X.shape[0], spec.width)), np.empty(X.shape[0], dtype=np.int64)
        rows(X, P, out, status)
        return out, status

    out, status = run(X, P)
    assert (status == OK).sum() >= n // 2, np.unique(status, return_counts=True)
    for i in range(n):
        alone, code = run(X[i : i + 1], P[i : i + 1])
        assert code[0] == status[i], i
        np.testing.assert_array_equal(alone[0], out[i])
    two, codes = run(X[:5], np.ascontiguousarray(P[:2]))
    served = np.ascontiguousarray(np.repeat(P[1:2], 4, axis=0))
    np.testing.assert_array_equal(two[1:], run(X[1:5], served)[0])
    np.testing.assert_array_equal(codes[1:], run(X[1:5], served)[1])
    shared, codes = run(X, np.ascontiguousarray(P[:1]))
    np.testing.assert_array_equal(shared, run(X, np.repeat(P[:1], n, axis=0))[0])


@pytest.mark.parametrize("p", [3, -3, 5, -5, 7, -7])
def test_half_integer_powers_print_as_square_roots(p):
    """b**(p/2) prints as a multiplication and a square root (no libm pow: derive/printer.py), and
    equals b**(p/2) to within 4 ulp (measured over these 2,000 bases: 1 ulp for p = 3, 2 for
    -3, +-5 and 7, 3 for -7; only p = +-3 occurs in generated/). Evaluated by CPython, whose b**2
    is libm's pow where numba multiplies: the same to an ulp."""
    from slipmaps.derive.printer import to_code

    x = sp.Symbol("x", positive=True)
    code = to_code(x ** sp.Rational(p, 2))
    assert "**(" not in code and "math.sqrt(x)" in code, code
    bases = np.exp(_rng(f"half_power{p}").uniform(-30.0, 30.0, 2000))
    got = np.array([eval(code, {"math": math, "x": float(b)}) for b in bases])  # noqa: S307 - printed code
    ref = bases ** (p / 2)
    assert np.all(np.abs(got - ref) <= 4 * np.spacing(np.abs(ref))), np.max(
        np.abs(got - ref) / np.spacing(ref)
    )


def test_generated_code_has_no_fractional_power_of_a_constant():
    """No constant non-integer exponent is left in generated/ (each one was a half-integer, printed
    with square roots now; an exponent such as 3/4 would need its own printing, or a pow call
    allowed here). Runtime exponents, such as a contraction factor's power of the pass count,
    remain."""
    pattern = re.compile(r"\*\*\(-?\d+\.\d+\)")  # as SymPy prints a constant non-integer exponent
    found = {
        path.name: pattern.findall(path.read_text())
        for path in (Path(generate.__file__).resolve().parents[1] / "generated").glob("*.py")
    }
    assert len(found) > 10 and not any(found.values()), {n: f for n, f in found.items() if f}
