"""Render every generated file from the derivations, or check that the committed ones are current.

Files: ``generated/status.py``; one kernel module per :class:`~.ir.Module` of the model
(``slip_model``, ``flight``) and per declared map (:func:`.maps.all_maps`); ``generated/maps_index.py``
(the index the runtime reads); ``generated/support.py`` (what the kernels share: stack arrays, a
row's store and checks); ``generated/__init__.py``; ``docs/equations.md`` (+ ``.json``, the
record the report's sections 6-8 read) and ``docs/maps.md``; the maps that take the leg damping in
``docs/damping.md``; the equation summary and the short map
table of ``README.md`` and the report equations of each family page (:func:`family_pages`), between
their markers.

Deterministic: the same sources give byte-identical files (no timestamps, SymPy pinned, ordered
CSE, ``repr`` floats). Files are written only when their content changes, so numba's on-disk
cache (keyed on the file's modification time and size) stays valid for unchanged modules. A
module that calls kernels of another records that module's content hash in its header.
"""

from __future__ import annotations

import difflib
import hashlib
import json
import re
from pathlib import Path

import jinja2
import sympy as sp

from . import docs, numerics
from .equations import entries, render_equation_record, render_equation_summary, render_equation_table
from .ir import Module, calls
from .lower import SUPPORT_MODULE, filled, lower
from .maps import all_halves, all_maps, ground_truth
from .maps import family_pages as all_family_pages
from .mapspec import MapSpec
from .model import simulation
from .model.kernels import MODULES as MODEL_MODULES
from .model.kernels import PUBLIC as PUBLIC_MODULE
from .model.kernels import flight_kernels, public_kernels
from .render import render
from .share import share_bodies
from .status import STATUS_CODES
from .tangent import Differentiator, widened
from .wrap import dense, intern_repeats, wrap

ROOT = Path(__file__).resolve().parent.parent
GENERATED = ROOT / "generated"

VERSIONS = {"sympy": sp.__version__, "jinja2": jinja2.__version__}


def _pieces(text: str, width: int = 80) -> list[str]:
    """``text`` in pieces of at most about ``width`` characters, split after spaces (adjacent string
    literals in the generated file, which Python joins)."""
    out, current = [], ""
    for word in text.split(" "):
        if current and len(current) + len(word) > width:
            out.append(current)
            current = ""
        current += word + " "
    out.append(current[:-1])
    return out


def _literal(text: str) -> str:
    """``text`` as adjacent string literals of at most about 80 characters (jinja2's ``tojson``
    escapes), one a line."""
    pieces = [json.dumps(p).translate(_HTML_SAFE) for p in _pieces(text)]
    return "\n        ".join(pieces)


_HTML_SAFE = str.maketrans({"<": "\\u003c", ">": "\\u003e", "&": "\\u0026", "'": "\\u0027"})
_STATUSES = [{"name": n, "code": c, "message": msg, "literal": _literal(msg)} for n, c, msg in STATUS_CODES]


def _sha(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _require_checkout() -> None:
    if not (ROOT / "pyproject.toml").is_file():
        raise ValueError(
            f"slipmaps generate works on a source checkout (pip install -e '.[derive]'); "
            f"{ROOT} has no pyproject.toml"
        )


#: The generator's numerical support modules (hand-written algorithms rendered from derive/templates/
#: with data from derive/numerics.py): name -> (template, data, the generated modules it imports
#: besides status and support). A kernel module calling into one imports it like any other.
NUMERICS = {
    "dop853": ("dop853.py.j2", numerics.dop853, ("support",)),
    "exact_stance": ("exact_stance.py.j2", numerics.exact_stance, ("dop853", "slip_model")),
}


def _callee_modules(mod: Module) -> set[str]:
    """The other kernel modules whose kernels ``mod``'s kernels call (not the support modules)."""
    found = {c.kernel.module for kernel in mod.kernels() for c in calls(kernel.steps)}
    return found - set(NUMERICS) - {mod.name}


def _render_numerics(name: str, files: dict[str, str]) -> None:
    """``generated/<name>.py``, a numerical support module (:data:`NUMERICS`), into ``files`` (after
    the modules it imports, whose content hashes its header records)."""
    template, data, imports = NUMERICS[name]
    for dep in imports:
        if dep in NUMERICS and f"generated/{dep}.py" not in files:
            _render_numerics(dep, files)
    missing = [d for d in imports if f"generated/{d}.py" not in files]
    if missing:
        raise ValueError(f"support module {name} imports {missing}, which must be generated before it")
    files[f"generated/{name}.py"] = wrap(
        render(
            template,
            source="derive/numerics.py",
            template=f"derive/templates/{template}",
            depends=[{"name": f"{d}.py", "sha256": _sha(files[f"generated/{d}.py"])} for d in imports],
            versions=VERSIONS,
            **data(),
        )
    )


def _jacobian_modules(primal: tuple[Module, ...], flights) -> tuple[Module, ...]:
    """The Jacobian kernels of every map (:meth:`MapSpec.jacobian_kernels`) and of the kernels they
    call, one module ``<module>_jacobian`` per module of the differentiated kernels."""
    widen: dict = {}
    for _ in range(2):  # the second pass with one vector JVP per callee for all its callers' patterns
        diff = Differentiator(widen=widen)
        for spec in (*all_maps(), ground_truth()):
            spec.jacobian_kernels(diff, flights)
        diff.build()
        widen = widened(diff.asked)
        if not widen:
            break
    by_module: dict[str, list] = {}
    for kernel in diff.kernels.values():
        by_module.setdefault(kernel.module, []).append(kernel)
    sources = {m.name: m for m in primal}
    out = []
    for name, kernels in by_module.items():
        base = sources[name.removesuffix("_jacobian")]
        out.append(
            Module(
                name=name,
                doc=f"Derivatives (forward mode, derive/tangent.py) of the kernels of module {base.name}: "
                "JVP kernels, and for a map its stance and apex-return Jacobians.",
                source=base.source,
                kernels=lambda kernels=tuple(kernels): kernels,
            )
        )
    return tuple(out)


def _primal(flights) -> tuple[tuple[Module, ...], tuple[Module, ...]]:
    """The maps' modules (in report order, the exact map last) and the halves'."""
    maps = MapSpec.modules((*all_maps(), ground_truth()), flights)
    return maps, tuple(half.module() for half in all_halves())


def primal_modules() -> tuple[Module, ...]:
    """The kernel modules without the Jacobians' (a third of the build's time less): the model's, the
    maps', the halves' and the public one."""
    maps, halves = _primal(flight_kernels())
    return MODEL_MODULES + maps + halves + (PUBLIC_MODULE,)


def modules() -> tuple[Module, ...]:
    """Every generated kernel module, callees before callers (otherwise model, maps in report
    order, their Jacobians, halves)."""
    flights = flight_kernels()
    maps, halves = _primal(flights)
    jacobians = _jacobian_modules(MODEL_MODULES + maps, flights)
    pending = list(MODEL_MODULES + maps + jacobians + halves + (PUBLIC_MODULE,))
    needs = {mod.name: _callee_modules(mod) for mod in pending}
    done: list[Module] = []
    while pending:
        ready = next((m for m in pending if needs[m.name] <= {d.name for d in done}), None)
        if ready is None:
            raise ValueError(f"generated modules call each other in a cycle: {[m.name for m in pending]}")
        done.append(ready)
        pending.remove(ready)
    return tuple(done)


_FUNC_REF = re.compile(r":func:`[\w.]+`")


def _doc_key(k: dict) -> tuple:
    """What a kernel's docstrings say besides its summary and equations: notes, arguments, returns,
    status and batch form (derive/templates/kernels.py.j2; the summary line is every kernel's
    own). A derivative kernel's reference to the kernel it differentiates counts as the same: its
    arguments (in the key) are that kernel's."""
    doc_args = _FUNC_REF.sub(":func:", k["doc_args"])
    returns = _FUNC_REF.sub(":func:", repr(k["returns"]))
    return (k["notes"], repr(k["args"]), doc_args, returns, k["status"]) + (
        k["n_out"],
        repr(k["layout"]),
        k["out_array"],
    )


def _share_docs(kernels: list[dict]) -> None:
    """A kernel whose docstring would repeat an earlier kernel's of the module word for word (the
    choices of a specialized option: the same arguments, returns and statuses) refers to that
    kernel's instead (``doc_ref``; for its equations too where they are the same,
    ``doc_ref_equations``): each choice's kernel and batch form still say what they are, the module
    says the rest once."""
    first: dict[tuple, dict] = {}
    for k in kernels:
        k["doc_ref"], k["doc_ref_equations"] = "", False
        if k["shared_by"]:  # a shared body's docstring says what it is (derive/share.py)
            continue
        ref = first.setdefault(_doc_key(k), k)
        if ref is not k:
            # the equations too, where they are the same (they are not part of the key)
            same = bool(k["equations"]) and ref["equations"] == k["equations"]
            k["doc_ref"], k["doc_ref_equations"] = ref["name"], same


def _render_module(mod: Module, kernels: list[dict], files: dict[str, str]) -> str:
    """The source of module ``mod`` from its lowered kernels; ``files`` holds every generated module
    it imports (rendered before it), whose content hashes go into its header."""
    callees: dict[str, set[str]] = {}
    for k in kernels:
        for module, name in k["callees"]:
            callees.setdefault(module, set()).add(name)
    generated = sorted(callees)
    for m in generated:
        if m in NUMERICS and f"generated/{m}.py" not in files:
            _render_numerics(m, files)
    missing = [m for m in generated if f"generated/{m}.py" not in files]
    if missing:
        raise ValueError(f"module {mod.name} calls into {missing}, which must be generated before it")
    depends = [{"name": f"{m}.py", "sha256": _sha(files[f"generated/{m}.py"])} for m in generated]
    imports = [f"from .{m} import {', '.join(sorted(callees[m]))}" for m in generated]
    if any(k["support"] for k in kernels):
        depends.insert(
            0, {"name": f"{SUPPORT_MODULE}.py", "sha256": _sha(files[f"generated/{SUPPORT_MODULE}.py"])}
        )
    return wrap(
        render_kernels(kernels, source=mod.source, module_doc=mod.doc, depends=depends, imports=imports)
    )


def _table_code(values: list) -> str:
    """A lookup table's module constant: ``np.array(...)`` of its values by code (NaN as ``NAN``)."""

    def fmt(v) -> str:
        if isinstance(v, list):
            return "[" + ", ".join(fmt(x) for x in v) + "]"
        return "NAN" if v != v else repr(float(v))

    rows = [fmt(v) for v in filled(values)]
    return "np.array([" + ", ".join(rows) + "])"


def render_kernels(
    kernels: list[dict],
    *,
    source: str,
    module_doc: str,
    depends: list[dict],
    imports: list[str],
    status_module: str = ".status",
    support_module: str = f".{SUPPORT_MODULE}",
) -> str:
    """The source of one kernel module (before :func:`.wrap.wrap`) from its lowered kernels
    (:func:`.lower.lower`): the docstrings its kernels share written once (:func:`_share_docs`), the
    statuses they use imported from ``status_module``. (A check of the inputs shared the same way,
    one njit function per module, saved 1,578 generated lines but slowed iterative's first calls
    from 3.5-3.6 / 8.8-9.2 s to 3.8-4.0 / 9.1-9.7 s: the kernels keep their own.)"""
    _share_docs(kernels)
    used = set().union(*(k["statuses"] for k in kernels))
    tables = {name: values for k in kernels for name, values in k["tables"].items()}
    return render(
        "kernels.py.j2",
        source=source,
        template="derive/templates/kernels.py.j2",
        depends=depends,
        module_doc=module_doc,
        imports=imports,
        support=any(k["support"] for k in kernels),
        tables=[(name, _table_code(values)) for name, values in sorted(tables.items())],
        kernels=kernels,
        versions=VERSIONS,
        statuses=[st["name"] for st in _STATUSES if st["name"] in used],
        status_module=status_module,
        support_module=support_module,
    )


def _index(specs: tuple[MapSpec, ...]) -> dict:
    from . import catalog
    from .halfspec import HALF_OUTPUTS

    flights = flight_kernels()

    def rows(group) -> list[dict]:
        return [{"name": f.name, "doc": f.doc, "unit": f.unit, "odd": f.odd} for f in group.fields()]

    return {
        "STANCE_OUTPUTS": rows(catalog.STANCE),
        "APEX_OUTPUTS": rows(catalog.APEX_RETURN),
        "TRAJECTORY_OUTPUTS": rows(catalog.TRAJECTORY),
        "HALF_OUTPUTS": rows(HALF_OUTPUTS),
        "GROUPS": {
            **catalog.STANCE.subgroups(),
            **catalog.APEX_RETURN.subgroups(),
            **HALF_OUTPUTS.subgroups(),
        },
        "TOUCHDOWN": [a.name for a in catalog.TOUCHDOWN],
        "APEX_PUBLIC": dict(catalog.APEX_PUBLIC),
        "MAPS": [s.index_row(flights) for s in specs],
        "HALVES": [h.index_row() for h in all_halves()],
        "EXACT": ground_truth().index_row(flights),
        "MODEL": {name: k.signature() for name, k in public_kernels().items()},
        "SIMULATION": dict(simulation.SETTINGS),
        "REST_LENGTH_TOLERANCE": catalog.REST_LENGTH_TOLERANCE,
    }


#: The generated package's modules that are not kernel modules of a declaration.
OWN_MODULES = frozenset({"status", "maps_index", SUPPORT_MODULE, "__init__", *NUMERICS})


def check_module_names(mods) -> None:
    """Refuse a kernel module (a declared map's, say) named like one of :data:`OWN_MODULES`: it would
    overwrite that module."""
    taken = sorted({m.name for m in mods} & OWN_MODULES)
    if taken:
        raise ValueError(f"kernel modules {taken}: these names are the generated package's own modules")


def build_files() -> dict[str, str]:
    """Every generated file as {path relative to the repository root: content}."""
    _require_checkout()
    files: dict[str, str] = {}
    common = {"versions": VERSIONS, "statuses": _STATUSES}
    files["generated/status.py"] = wrap(
        render(
            "status.py.j2",
            source="derive/status.py",
            template="derive/templates/status.py.j2",
            depends=[],
            **common,
        )
    )
    # the index first: the exact simulator's package reads its columns (a dependency of its callers)
    specs = all_maps()
    index = _index(specs)
    files["generated/maps_index.py"] = wrap(
        render(
            "maps_index.py.j2",
            source="derive/mapspec.py",
            template="derive/templates/maps_index.py.j2",
            depends=[],
            tables=[
                # the first line holds "NAME = " too: every line within the limit
                (name, dense(value, first=len(name) + 3))
                for name, value in intern_repeats(index)
            ],
            **common,
        )
    )
    mods = modules()
    check_module_names(mods)
    lowered = {mod.name: [lower(k) for k in mod.kernels()] for mod in mods}
    lowered = {name: share_bodies(ks) for name, ks in lowered.items()}
    files[f"generated/{SUPPORT_MODULE}.py"] = wrap(
        render(
            "support.py.j2",
            source="derive/templates/support.py.j2",
            template="derive/templates/support.py.j2",
            depends=[],
            **common,
        )
    )
    for mod in mods:
        files[f"generated/{mod.name}.py"] = _render_module(mod, lowered[mod.name], files)
    files["generated/__init__.py"] = wrap(
        render(
            "init.py.j2",
            source="derive/generate.py",
            template="derive/templates/init.py.j2",
            depends=[],
            modules=[{"name": m.name, "doc": m.doc} for m in mods],
            **common,
        )
    )
    table = render_equation_table()
    files["docs/equations.md"] = table
    files["docs/equations.json"] = render_equation_record()
    files["docs/maps.md"] = docs.maps_page(index)
    files.update(family_pages())
    # the page may be a family page too (geyer-damped's): its equations are already in ``files``
    damping = files.get("docs/damping.md") or (ROOT / "docs/damping.md").read_text()
    files["docs/damping.md"] = docs.replace_between(
        damping, "maps", docs.parameter_maps(index, "c"), "docs/damping.md"
    )
    readme = (ROOT / "README.md").read_text()
    readme = docs.replace_between(readme, "equations", render_equation_summary())
    readme = docs.replace_between(readme, "maps", docs.readme_maps_table(index))
    files["README.md"] = readme
    return files


def family_pages() -> dict[str, str]:
    """Every family page ``docs/<page>.md`` (:func:`.maps.family_pages`) with the report equations of
    its maps (:func:`.docs.family_equations`) between its markers ``<!-- equations:begin -->`` and
    ``<!-- equations:end -->``; the rest of the page is hand-written, read from the checkout."""
    registry = entries()
    out = {}
    for page, specs in all_family_pages().items():
        rel = f"docs/{page}.md"
        if not (ROOT / rel).is_file():
            names = ", ".join(f"`{s.name}`" for s in specs)
            raise ValueError(
                f"{names}: no family page {rel}; write it (with the markers <!-- equations:begin --> and "
                "<!-- equations:end -->) or set PAGE = '<an existing page>' in the map's module"
            )
        text = (ROOT / rel).read_text()
        out[rel] = docs.replace_between(text, "equations", docs.family_equations(specs, registry), rel)
    return out


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
