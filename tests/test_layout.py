"""The runtime's layout (runtime/__init__.py): subpackages by job, imports one way, no circle.

Read from the sources (``ast``), every import counted, also those inside functions:

- a module of ``runtime/<package>/`` imports only from packages at its level or below:
  ``api`` < ``exact``, ``robot`` < ``analysis``, ``sweep``, ``control`` < ``studies`` (the robot
  study runs the controllers), ``export`` < ``report`` < ``cli`` (the top-level package
  ``runtime/public`` sits above them all); a backend is found by name from the index, not imported
  by the API;
- the modules' import graph has no cycle;
- no module imports another's private name (``from .x import _y``);
- the runtime never imports ``derive`` but its plain-data parameter table (``derive/params.py``).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
RUNTIME = ROOT / "runtime"
RANK = {
    "api": 0,
    "exact": 1,
    "robot": 1,
    "analysis": 2,
    "sweep": 2,
    "control": 2,
    "studies": 3,
    "export": 3,
    "report": 4,
    "cli": 5,
    "public": 6,
}


def _modules() -> dict[str, Path]:
    """Dotted name (``runtime.api.maps``) -> path, for every module of the runtime."""
    out = {}
    for path in sorted(RUNTIME.rglob("*.py")):
        rel = path.relative_to(ROOT).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


MODULES = _modules()


def _resolve(module: str, node: ast.ImportFrom | ast.Import) -> list[tuple[str, list[str]]]:
    """(imported module in ``runtime.``/``derive.``/``generated.`` form, names) of one import."""
    if isinstance(node, ast.Import):
        return [(a.name.removeprefix("slipmaps."), []) for a in node.names if a.name.startswith("slipmaps.")]
    names = [a.name for a in node.names]
    if node.level == 0:
        if not (node.module or "").startswith("slipmaps"):
            return []
        base = node.module.removeprefix("slipmaps").removeprefix(".")
        base = base or "runtime.public"
    else:
        package = module.split(".") if MODULES[module].name == "__init__.py" else module.split(".")[:-1]
        package = package[: len(package) - (node.level - 1)]
        base = ".".join(package + ([node.module] if node.module else []))
    if base.startswith("runtime.") or base == "runtime":
        # ``from . import x``: x may be a submodule
        subs = [f"{base}.{n}" for n in names if f"{base}.{n}" in MODULES]
        if subs:
            return [(s, []) for s in subs]
    return [(base, names)]


def _imports() -> dict[str, list[tuple[str, list[str]]]]:
    out = {}
    for module, path in MODULES.items():
        found = []
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                found += _resolve(module, node)
        out[module] = found
    return out


IMPORTS = _imports()


def _package(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 2 or (len(parts) == 2 and parts[1] in RANK) else None


def test_every_runtime_module_is_in_a_subpackage():
    loose = [
        m for m in MODULES if m.count(".") == 1 and m.split(".")[1] not in RANK and m != "runtime.__main__"
    ]
    assert loose == [], loose
    packages = {_package(m) for m in MODULES} - {None}
    assert (
        packages <= set(RANK)
        and {"api", "exact", "analysis", "sweep", "studies", "cli", "public"} <= packages
    )


def test_imports_run_one_way():
    wrong = []
    checked = 0
    for module, found in IMPORTS.items():
        mine = _package(module)
        for target, _ in found:
            if not target.startswith("runtime.") or mine is None:
                continue
            theirs = _package(target)
            if theirs is None or theirs == mine:
                continue
            checked += 1
            if RANK[theirs] > RANK[mine] or (RANK[theirs] == RANK[mine] and theirs != "analysis"):
                wrong.append(f"{module} imports {target}")
    assert checked > 50, checked  # the check saw the cross-package imports
    assert wrong == [], "\n".join(wrong)


def test_no_import_cycle():
    graph = {m: sorted({t for t, _ in found if t in MODULES and t != m}) for m, found in IMPORTS.items()}
    state: dict[str, int] = {}
    cycles = []

    def visit(node: str, path: list[str]) -> None:
        state[node] = 1
        for nxt in graph[node]:
            # a package's __init__ is imported with any of its modules: not an edge back
            if node.startswith(nxt + "."):
                continue
            if state.get(nxt) == 1:
                cycles.append(path[path.index(nxt) :] + [nxt] if nxt in path else [node, nxt])
            elif nxt not in state:
                visit(nxt, [*path, nxt])
        state[node] = 2

    for m in graph:
        if m not in state:
            visit(m, [m])
    assert sum(len(v) for v in graph.values()) > 100
    assert cycles == [], cycles


def test_no_private_name_is_imported_from_another_module():
    private = [
        f"{module}: from {target} import {name}"
        for module, found in IMPORTS.items()
        for target, names in found
        for name in names
        if name.startswith("_") and not name.startswith("__")
    ]
    assert private == [], "\n".join(private)


def test_the_runtime_reads_only_the_parameter_table_of_derive():
    reads = sorted({t for found in IMPORTS.values() for t, _ in found if t.startswith("derive")})
    assert reads == ["derive"] or reads == ["derive.params"], reads


@pytest.mark.parametrize("constant", ["EXACT"])
def test_one_definition_per_constant(constant):
    where = [
        m
        for m, path in MODULES.items()
        for node in ast.parse(path.read_text()).body
        if (isinstance(node, ast.Assign) and any(getattr(t, "id", None) == constant for t in node.targets))
        or (isinstance(node, ast.AnnAssign) and getattr(node.target, "id", None) == constant)
    ]
    assert len(where) == 1, where
