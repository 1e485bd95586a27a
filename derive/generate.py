"""Render every generated file from the derivations, or check that the committed ones are current.

Deterministic: the same sources give byte-identical files (no timestamps, SymPy pinned, ordered
CSE, ``repr`` floats). Files are written only when their content changes, so numba's on-disk
cache (keyed on the file's modification time and size) stays valid for unchanged modules.
"""

from __future__ import annotations

import difflib
import hashlib
from pathlib import Path

import jinja2
import sympy as sp

from .kernel import lower
from .modules import MODULES
from .render import render
from .status import STATUS_CODES

ROOT = Path(__file__).resolve().parent.parent
GENERATED = ROOT / "generated"
DOCS = ROOT / "docs"

VERSIONS = {"sympy": sp.__version__, "jinja2": jinja2.__version__}
_STATUSES = [{"name": n, "code": c, "message": msg} for n, c, msg in STATUS_CODES]


def _sha(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()[:16]


_with_docs = False


def build_files() -> dict[str, str]:
    """Every generated file as {path relative to the repository root: content}."""
    files: dict[str, str] = {}
    common = {"versions": VERSIONS, "statuses": _STATUSES}
    files["generated/status.py"] = render(
        "status.py.j2", source="derive/status.py", template="derive/templates/status.py.j2", depends=[], **common
    )
    for spec in MODULES:
        depends = [{"name": f"{d}.py", "sha256": _sha(files[f"generated/{d}.py"])} for d in spec.depends]
        files[f"generated/{spec.name}.py"] = render(
            "kernels.py.j2",
            source=spec.source,
            template="derive/templates/kernels.py.j2",
            depends=depends,
            module_doc=spec.doc,
            imports=list(spec.imports),
            apex_returns=list(spec.apex_returns),
            kernels=[lower(k) for k in spec.build()],
            **common,
        )
    files["generated/__init__.py"] = render(
        "init.py.j2",
        source="derive/modules.py",
        template="derive/templates/init.py.j2",
        depends=[],
        modules=[{"name": s.name, "doc": s.doc} for s in MODULES],
        **common,
    )
    if _with_docs:
        from .registry import render_equation_table  # late: the registry derives the whole report

        files["docs/equations.md"] = render_equation_table()
    return files


def _stale(files: dict[str, str]) -> list[str]:
    present = {f"generated/{p.name}" for p in GENERATED.glob("*.py")}
    return sorted(present - set(files))


def write(files: dict[str, str] | None = None) -> list[str]:
    """Write changed files and delete stale generated modules; returns the paths touched."""
    files = build_files() if files is None else files
    touched = []
    for rel, text in files.items():
        path = ROOT / rel
        if path.exists() and path.read_text() == text:
            continue
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        touched.append(rel)
    for rel in _stale(files):
        (ROOT / rel).unlink()
        touched.append(rel)
    return touched


def check(files: dict[str, str] | None = None) -> list[str]:
    """Unified diffs (one per out-of-date file); empty when everything is current."""
    files = build_files() if files is None else files
    problems = []
    for rel, text in files.items():
        path = ROOT / rel
        old = path.read_text() if path.exists() else ""
        if old != text:
            diff = difflib.unified_diff(
                old.splitlines(True), text.splitlines(True), f"a/{rel} (committed)", f"b/{rel} (from sources)"
            )
            problems.append("".join(diff) or f"{rel}: missing")
    for rel in _stale(files):
        problems.append(f"{rel}: stale file, not produced by the sources (delete it)")
    return problems


def main(check_only: bool = False) -> int:
    """Entry point of ``slipmaps generate [--check]``."""
    if check_only:
        problems = check()
        for p in problems:
            print(p)
        if problems:
            print(f"{len(problems)} generated file(s) out of date: run `slipmaps generate`.")
            return 1
        print("generated files are current")
        return 0
    touched = write()
    print("\n".join(f"wrote {t}" for t in touched) or "generated files already current")
    return 0
