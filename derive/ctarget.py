"""The C target of the generator: every analytic map's role kernels as one dependency-free C99
library, from the same declarations and the same lowering as the numba kernels.

``slipmaps generate --target c DIR`` writes ``DIR/slipmaps.h`` and ``DIR/slipmaps.c`` (the
maps) and ``DIR/slipmaps_deadbeat.h`` and ``DIR/slipmaps_deadbeat.c`` (the deadbeat solver: a port of
the numba solver, runtime/control/compiled.py, on any exported map's role kernels) and
``DIR/slipmaps_swing.h``, ``DIR/slipmaps_swing.c`` (the swing-leg policy's evaluation, a port of
runtime/control/swing_tables.py, on tables ``slipmaps.swing_policy`` makes). The kernels are
the ones :func:`.generate.modules` declares, lowered by :func:`.lower.lower` once; the C template
(``templates/c/kernels.c.j2``) renders the lowered steps as the numba template does, each piece of
code printed by :mod:`.cexpr`. What the library holds:

- every role kernel (a map's ``stance``, ``apex_return``, ``state_at``, their Jacobians, the
  halves' and the flights' roles) as ``int slipmaps_<kernel>_v(const double *x, const double *p,
  double *out)``, the vectors of the generated index's layouts (the same positions), and as
  ``int slipmaps_<kernel>(const slipmaps_<kernel>_x *x, const slipmaps_<params> *p,
  slipmaps_<kernel>_out *out)`` on structs with the layouts' names as fields;
- the status codes as ``enum slipmaps_status`` (the codes of derive/status.py);
- every other kernel as a ``static`` function of the library (the calling conventions of
  derive/lower.py's ``abi``: a kernel of at most 16 values returns them in an array ``_r`` with its
  status last, one of more writes an array ``out``).

The exact simulator is not exported (its DOP853 integrator is a numba template, not a declaration):
nor is any kernel that calls it. No heap, no global state, only ``<math.h>``.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from pathlib import Path

from .cexpr import C_RESERVED, CPrintError, cexpr, cstatements
from .ir import MAX_NODES, Kernel, calls
from .lower import abi, filled, lower
from .render import render, template
from .status import STATUS_CODES

#: What the C library's files are called in the output directory: the maps, the deadbeat solver.
HEADER, SOURCE = "slipmaps.h", "slipmaps.c"
DEADBEAT_HEADER, DEADBEAT_SOURCE = "slipmaps_deadbeat.h", "slipmaps_deadbeat.c"
SWING_HEADER, SWING_SOURCE = "slipmaps_swing.h", "slipmaps_swing.c"
SOURCES = (SOURCE, DEADBEAT_SOURCE, SWING_SOURCE)


def _reaches_external(kernel: Kernel, memo: dict[str, bool]) -> bool:
    if kernel.name in memo:
        return memo[kernel.name]
    hit = kernel.external or any(_reaches_external(c.kernel, memo) for c in calls(kernel.steps))
    memo[kernel.name] = hit
    return hit


def exported(modules) -> tuple[list[Kernel], list[Kernel]]:
    """The role kernels the C library exports (every one that does not reach the exact simulator)
    and every kernel they call, callees first."""
    memo: dict[str, bool] = {}
    roles = [
        k for mod in modules for k in mod.kernels() if k.layout is not None and not _reaches_external(k, memo)
    ]
    order: list[Kernel] = []
    seen: set[str] = set()

    def visit(k: Kernel) -> None:
        if k.name in seen:
            return
        seen.add(k.name)
        for c in calls(k.steps):
            visit(c.kernel)
        order.append(k)

    for k in roles:
        visit(k)
    return roles, order


class _Kernel:
    """One kernel's C: its signature and return kind, and its lowered body printed as C."""

    def __init__(self, kernel: Kernel, data: dict, kinds: dict[str, str]):
        self.kernel, self.data, self.kinds = kernel, data, kinds
        self.how = abi(kernel)
        self.arrays: dict[str, str] = {}  # name -> C declarator suffix ("[12]", "[3][7]")
        self.pointers: dict[str, str] = {}  # lookup binds of a table's vector or matrix
        self.ints: set[str] = set()
        self.assigned: list[str] = []
        for name in data["arrays"]:
            self.arrays[name] = f"[{MAX_NODES}]"
        if data["rows"]:
            self.arrays["_T"] = f"[{data['rows']}][{data['directions']}]"
        self.kind = kinds[kernel.name]
        self.n_out = data["n_out"]

    # ---- the statement nodes, printed -------------------------------------------------------
    def fail(self, code: str) -> str:
        if self.kind == "out":
            return f"return slipmaps_fail_(out, {self.n_out}, {code});"
        if self.kind == "tuple_status":
            return f"return slipmaps_fail_r_(_r, {self.n_out}, {code});"
        raise CPrintError(f"kernel {self.kernel.name}: fails without a status")

    def _assign(self, name: str) -> None:
        if name not in self.assigned:
            self.assigned.append(name)

    def statements(self, lines: Iterable[str]) -> list[str]:
        out: list[str] = []
        for line in lines:
            stmts, arrays = cstatements(line)
            for name, n in arrays.items():
                self.arrays[name] = f"[{n}]"
            for s in stmts:
                m = re.match(r"([A-Za-z_]\w*) =", s)
                if m:
                    self._assign(m.group(1))
            out += stmts
        return out

    def nodes(self, nodes: list[dict]) -> list[dict]:
        return [self.node(n) for n in nodes]

    def node(self, n: dict) -> dict:
        kind = n["kind"]
        if kind == "comment":
            return {"kind": "comment", "text": n["text"].replace("*/", "* /")}
        if kind == "assign":
            self._assign(n["name"])
            return {"kind": "line", "code": f"{n['name']} = {cexpr(n['code'])};"}
        if kind == "guard":
            return {
                "kind": "guard",
                "doc": n["doc"].replace("*/", "* /"),
                "code": cexpr(n["code"]),
                "fail": self.fail("SLIPMAPS_STATUS_" + n["status"]),
            }
        if kind in ("call", "tail"):
            return self.call(n)
        if kind == "loop":
            return self.loop(n)
        if kind == "store":
            return {
                "kind": "lines",
                "lines": [f"_T[{n['row']}][{j}] = {cexpr(c)};" for j, c in enumerate(n["codes"])],
            }
        if kind == "load":
            for nm in n["names"]:
                self._assign(nm)
            return {
                "kind": "lines",
                "lines": [f"{nm} = _T[{n['row']}][{j}];" for j, nm in enumerate(n["names"])],
            }
        if kind == "directions":
            self.ints.add(n["j"])
            for r in n["reads"]:
                self._assign(r["name"])
            return {
                "kind": "directions",
                "j": n["j"],
                "n": n["n"],
                "reads": [f"{r['name']} = _T[{r['row']}][{n['j']}];" for r in n["reads"]],
                "body": self.nodes(n["body"]),
                "writes": [f"_T[{w['row']}][{n['j']}] = {cexpr(w['code'])};" for w in n["writes"]],
            }
        if kind == "lookup":
            binds = []
            for b in n["binds"]:
                shape = self.data["_table_shapes"][b["const"]]
                if shape == "scalar":
                    self._assign(b["name"])
                else:
                    self.pointers[b["name"]] = shape
                binds.append(f"{b['name']} = {b['const']}[_code];")
            self.ints.add("_code")
            return {
                "kind": "lookup",
                "selector": cexpr(n["selector"]),
                "valid": cexpr(n["valid"]),
                "fail": self.fail("SLIPMAPS_STATUS_INVALID_INPUT"),
                "binds": binds,
            }
        if kind == "nodes":
            self.ints |= {n["j"], n["k"]}
            for r in n["reads"]:
                self._assign(r["name"])
            for sm in n["sums"]:
                self._assign(sm["name"])
            return {
                "kind": "nodes",
                "j": n["j"],
                "k": n["k"],
                "count": cexpr(n["count"]),
                "reads": [f"{r['name']} = {r['array']}[{n['j']}];" for r in n["reads"]],
                "sums": [
                    {
                        "name": sm["name"],
                        "code": f"{sm['matrix']}[{n['j']}][{n['k']}]*{sm['array']}[{n['k']}]",
                    }
                    for sm in n["sums"]
                ],
                "body": self.nodes(n["body"]),
                "writes": [f"{w['array']}[{n['j']}] = {cexpr(w['code'])};" for w in n["writes"]],
            }
        if kind == "reduce":
            self.ints.add(n["k"])
            for sm in n["sums"]:
                self._assign(sm["name"])
            return {
                "kind": "reduce",
                "k": n["k"],
                "count": cexpr(n["count"]),
                "sums": [{"name": sm["name"], "code": cexpr(sm["term"])} for sm in n["sums"]],
            }
        if kind == "switch":
            return {
                "kind": "switch",
                "selector": cexpr(n["selector"]),
                "cases": [{"value": cexpr(c["value"]), "body": self.nodes(c["body"])} for c in n["cases"]],
                "fail": self.fail("SLIPMAPS_STATUS_INVALID_INPUT"),
            }
        raise CPrintError(f"kernel {self.kernel.name}: no C for a {kind} node")

    def call(self, n: dict) -> dict:
        setup = self.statements(n["setup"])
        m = re.fullmatch(r"(\w+)\((.*)\)", n["expr"], re.S)
        if m is None:
            raise CPrintError(f"kernel {self.kernel.name}: no C for the call {n['expr']!r}")
        callee = m.group(1)
        args = [cexpr(a) for a in _split_args(m.group(2))]
        ckind = self.kinds[callee]
        if n["kind"] == "tail":
            if self.kind == "tuple_status":
                args.append("_r")
            expr = f"{callee}({', '.join(args)})"
            if self.data["layout"]:
                self.ints.add("_status")
                lines = [
                    f"_status = {expr};",
                    f"if (_status == SLIPMAPS_STATUS_OK && !slipmaps_finite_(out, {self.n_out})) {{",
                    f"    return slipmaps_fail_(out, {self.n_out}, SLIPMAPS_STATUS_NUMERICAL_RANGE);",
                    "}",
                    "return _status;",
                ]
            else:
                lines = [f"return {expr};"]
            return {"kind": "lines", "lines": setup + lines}
        var = n["var"]
        if ckind == "out":
            self.ints.add(var)
            call = f"{var} = {callee}({', '.join(args)});"
        elif ckind in ("tuple_status", "tuple"):
            self.arrays[var] = f"[{self.kinds['#n:' + callee]}]"
            call = f"{callee}({', '.join(args + [var])});"
        else:  # one value, no status
            self._assign(var)
            call = f"{var} = {callee}({', '.join(args)});"
        lines = setup + [call]
        status = None
        if n["status"]:
            status = {"code": cexpr(n["status"]), "fail": self.fail(f"(int){cexpr(n['status'])}")}
        binds = self.statements([n["load"]]) if n.get("load") else []
        for b in n["binds"]:
            self._assign(b["name"])
            binds.append(f"{b['name']} = {cexpr(b['code'])};")
        return {"kind": "call", "lines": lines, "status": status, "binds": binds}

    def loop(self, n: dict) -> dict:
        self.ints |= {n["it"], n["last"], n["conv"]}
        if n["a"]:
            self.ints.add(n["a"])
        for s in n["state"]:
            self._assign(s["name"])
        self._assign(n["count"])
        updates = []
        for u in n["updates"]:
            direct = u.get("direct", False)
            if not direct:
                self._assign(u["tmp"])
            updates.append(
                {
                    "direct": direct,
                    "tmp": cexpr(u["tmp"]),
                    "code": cexpr(u["code"]),
                    "name": u["name"],
                    "check": u["check"],
                    "scale": cexpr(u["scale"]) if u["check"] else "",
                }
            )
        return {
            "kind": "loop",
            "it": n["it"],
            "last": n["last"],
            "conv": n["conv"],
            "count": n["count"],
            "max_iter": cexpr(n["max_iter"]),
            "tol": cexpr(n["tol"]),
            "state": [{"name": s["name"], "code": cexpr(s["code"])} for s in n["state"]],
            "evaluate": self.nodes(n["evaluate"]),
            "body": self.nodes(n["body"]),
            "updates": updates,
            "fail_status": n["fail_status"],
            "fail": self.fail("SLIPMAPS_STATUS_" + n["fail_status"]) if n["fail_status"] else "",
            "arrays": [
                {
                    "name": a["name"],
                    "init": a["init"],
                    "next": a["next"],
                    "scale": cexpr(a["scale"]) if a["scale"] else "",
                }
                for a in n["arrays"]
            ],
            "nodes": cexpr(n["nodes"]) if n["arrays"] else "",
            "a": n["a"],
        }

    # ---- the function ------------------------------------------------------------------------
    def render_data(self) -> dict:
        k, d = self.kernel, self.data
        prologue = self.statements(d["prologue"])
        body = self.nodes(d["body"])
        guard = cexpr(d["input_guard"]) if d["input_guard"] else ""
        params = self.params()
        outputs = [
            {"name": o["name"], "code": cexpr(o["code"]), "checked": o["checked"]} for o in d["outputs"]
        ]
        store = self.statements([d["store"]]) if self.kind == "out" and not d["tail"] else []
        names = {p.rsplit(" ", 1)[-1].lstrip("*") for p in params.split(", ") if p != "void"}
        for name in (*self.assigned, *self.arrays, *self.pointers, *self.ints):
            if name in C_RESERVED:
                raise CPrintError(f"kernel {k.name}: the name {name!r} is reserved in C")
        ints = sorted(self.ints - names)
        doubles = [a for a in self.assigned if a not in names and a not in self.ints and a not in self.arrays]
        arrays = [f"{name}{dims}" for name, dims in self.arrays.items() if name not in names]
        pointers = [
            f"const double *{n}" if s == "vector" else f"const double (*{n})[{MAX_NODES}]"
            for n, s in self.pointers.items()
        ]
        return {
            "name": k.name,
            "summary": k.summary.replace("*/", "* /"),
            "equations": ", ".join(k.equations),
            "returns": self.returns(),
            "params": params,
            "param_names": sorted(names),
            "locals": ints + doubles + [a.split("[")[0] for a in arrays] + list(self.pointers),
            "ints": ints,
            "doubles": doubles,
            "arrays": arrays,
            "pointers": pointers,
            "prologue": prologue,
            "input_guard": guard,
            "body": body,
            "kind": self.kind,
            "layout": d["layout"],
            "tail": d["tail"],
            "status": d["status"],
            "check_outputs": d["check_outputs"],
            "outputs": outputs,
            "store": store,
            "n_out": self.n_out,
            "fail_invalid": self.fail("SLIPMAPS_STATUS_INVALID_INPUT") if d["input_guard"] else "",
            "fail_range": self.fail("SLIPMAPS_STATUS_NUMERICAL_RANGE") if d["status"] else "",
        }

    def returns(self) -> str:
        return {"out": "int", "tuple_status": "int", "tuple": "void", "value": "double"}[self.kind]

    def params(self) -> str:
        how, d = self.how, self.data
        if how.layout is not None:
            return "const double *x, const double *p, double *out"
        ps = ["const double *_a"] if how.args_array else [f"double {a['name']}" for a in d["args"]]
        if self.kind == "out":
            ps.append("double *out")
        elif self.kind in ("tuple", "tuple_status"):
            ps.append("double *_r")
        return ", ".join(ps) or "void"


_WRITE = re.compile(r"^\s*([A-Za-z_]\w*)(\[[^=]*\])?\s*\+?=(?!=)")


def _unread(function: str, names) -> list[str]:
    """The ``names`` a rendered C function body never reads (only assigns, or never mentions): the
    lowering keeps values some options do not use, which numba drops silently and a C compiler
    warns about (``-Wunused-but-set-variable``); the template casts exactly these to void."""
    reads: set[str] = set()
    for line in function.splitlines():
        m = _WRITE.match(line)
        text = line
        if m:  # the target is written, its indices and the right-hand side read
            text = (m.group(2) or "") + line[m.end() :]
        reads.update(re.findall(r"[A-Za-z_]\w*", text))
    return [n for n in names if n not in reads]


def _split_args(text: str) -> list[str]:
    """The top-level comma-separated arguments of a call's argument list."""
    out, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur)
    return out


def _kind(kernel: Kernel) -> str:
    how = abi(kernel)
    n = len(kernel.output_names)
    if how.out_array:
        return "out"
    if kernel.status:
        return "tuple_status"
    return "value" if n == 1 else "tuple"


def _table(values) -> str:
    """A lookup table's C initializer, by code (NaN where a code has no table)."""

    def fmt(v) -> str:
        if isinstance(v, list):
            return "{" + ", ".join(fmt(x) for x in v) + "}"
        return "NAN" if v != v else cexpr(repr(float(v)))

    return "{" + ", ".join(fmt(v) for v in filled(values)) + "}"


def _shape(values) -> str:
    first = next(v for v in values if v is not None)
    if not isinstance(first, list):
        return "scalar"
    return "matrix" if isinstance(first[0], list) else "vector"


def _comment(text: str) -> str:
    """``text`` safe inside a C comment, on one line."""
    return " ".join(text.replace("*/", "* /").split())


def _n_values(kernel: Kernel) -> int:
    """The values among a Jacobian role kernel's outputs (the derivatives, named ``d_...``, follow)."""
    names = kernel.output_names
    return next((i for i, n in enumerate(names) if n.startswith("d_") and "__" in n), len(names))


def build(modules, show: bool | None = False) -> dict[str, str]:
    """The C library's files {file name: content} for the kernel modules ``modules`` (callees
    first, :func:`.generate.modules`); ``show``: a progress bar over the kernels translated, on
    standard error (:class:`slipmaps.runtime.api.progress.Bar`; None: on a terminal after a second)."""
    from slipmaps.runtime.api.progress import Bar

    roles, order = exported(modules)
    kinds: dict[str, str] = {}
    for k in order:
        kinds[k.name] = _kind(k)
        kinds["#n:" + k.name] = len(k.output_names) + (1 if k.status else 0)
    tables: dict[str, tuple[str, str, str]] = {}
    functions = []
    for k in Bar(len(order), "translating the kernels to C", show, unit="kernels").count(order):
        data = lower(k)
        shapes = {}
        for name, values in data["tables"].items():
            shape = _shape(values)
            shapes[name] = shape
            dims = {"scalar": "", "vector": f"[{MAX_NODES}]", "matrix": f"[{MAX_NODES}][{MAX_NODES}]"}[shape]
            tables[name] = (f"[{len(values)}]{dims}", _table(values), shape)
        data["_table_shapes"] = shapes
        try:
            functions.append(_Kernel(k, data, kinds).render_data())
        except CPrintError as exc:
            raise CPrintError(f"kernel {k.name}: {exc}") from exc
    # each function's body rendered alone (the template's own macro), to find what it never reads
    empty = {"functions": [], "roles": [], "tables": [], "statuses": [], "max_nodes": MAX_NODES}
    body = template("c/kernels.c.j2").make_module({"helpers": (), **empty}).body
    for f in functions:
        f["unread"] = _unread(str(body(f)), f["param_names"] + f["locals"])
    # the parameter records: one struct per distinct p layout, named after the first role of a
    # module that takes it (a map's roles share one)
    # each map's options at their defaults, as kernel arguments (a choice's code): the header says them
    from slipmaps.runtime.api.index import halves, maps

    defaults = {info.module: info.encode(info.resolve({})) for info in (*maps(), *halves())}
    records: dict[tuple[str, ...], str] = {}
    records_docs: dict[str, dict[str, str]] = {}
    publics = []
    for k in roles:
        p = tuple(k.layout.p)
        if p not in records:
            base = k.module.removesuffix("_jacobian")
            name = f"slipmaps_{base}_params"
            while name in records.values():
                name = f"slipmaps_{k.name}_params"
            records[p] = name
        docs = {a.name: a.doc for a in k.args}
        out_docs = {f.name: f.doc + (f" [{f.unit}]" if f.unit else "") for f in k.outputs.fields()}
        n_values = _n_values(k)
        wrt = [
            n.split("__", 1)[1] for n in k.output_names[n_values:] if n.startswith(f"d_{k.output_names[0]}__")
        ]
        # a field's doc from any role that takes it as an argument
        rec_docs = records_docs.setdefault(records[p], {f: "" for f in p})
        rec_docs.update({f: _comment(docs[f]) for f in p if not rec_docs[f] and f in docs})
        for f, v in defaults.get(k.module.removesuffix("_jacobian"), {}).items():
            if f in rec_docs and "(default" not in rec_docs[f]:
                rec_docs[f] += f" (default {v:g})"
        publics.append(
            {
                "name": f"slipmaps_{k.name}",
                "x_docs": {f: _comment(docs.get(f, "")) for f in k.layout.x},
                "out_docs": {f: _comment(out_docs.get(f, "")) for f in k.output_names[:n_values]},
                "wrt": wrt,
                "kernel": k.name,
                "summary": k.summary.replace("*/", "* /"),
                "x": list(k.layout.x),
                "p": list(p),
                "params": records[p],
                "out": list(k.output_names),
                # the values (a Jacobian's derivatives follow them: d_<output>_d_<input>)
                "n_values": n_values,
                "module": k.module,
            }
        )
    statuses = [{"name": n, "code": c, "doc": d} for n, c, d in STATUS_CODES]
    common = {"statuses": statuses, "max_nodes": MAX_NODES}
    header = render(
        "c/slipmaps.h.j2",
        roles=publics,
        records=[{"name": n, "fields": list(p), "docs": records_docs[n]} for p, n in records.items()],
        **common,
    )

    def source(helpers) -> str:
        return render(
            "c/kernels.c.j2",
            functions=functions,
            roles=publics,
            tables=[{"name": n, "dims": t[0], "init": t[1]} for n, t in sorted(tables.items())],
            helpers=helpers,
            **common,
        )

    # the shared helpers the kernels call (a static function nothing calls is a warning)
    helpers = ("fail_", "fail_r_", "finite_", "min_", "max_")
    text = source(helpers)
    used = tuple(h for h in helpers if text.count(f"slipmaps_{h}(") > 1)
    source = source(used)
    # the deadbeat solver: a port of the numba solver (runtime/control/compiled.py), whose row head
    # it writes
    from slipmaps.runtime.control.compiled import HEAD

    solver = {"head": list(HEAD), "header": DEADBEAT_HEADER, **common}
    return {
        HEADER: header,
        SOURCE: source,
        DEADBEAT_HEADER: render("c/deadbeat.h.j2", **solver),
        DEADBEAT_SOURCE: render("c/deadbeat.c.j2", **solver),
        # the swing-leg policy's evaluation (runtime/control/swing_tables.py): tables made in Python
        SWING_HEADER: render("c/swing.h.j2", swing_header=SWING_HEADER, **common),
        SWING_SOURCE: render("c/swing.c.j2", swing_header=SWING_HEADER, **common),
    }


def write(directory: Path, stage=None, show: bool | None = False) -> list[Path]:
    """Write the C library into ``directory`` (created if missing); the paths written. ``stage``
    (``stage(what)``) is told each stage as it starts (deriving the kernels, about 12 s on a 2-core
    EPYC; translating them, 20 s; writing), ``show`` draws a bar over the kernels (:func:`build`)."""
    from .generate import modules

    say = stage if stage is not None else (lambda what: None)
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    say("deriving the kernel modules from derive/ (SymPy)")
    derived = modules()
    say("translating the kernels to C")
    files = build(derived, show)
    say(f"writing the C library into {directory}")
    written = []
    for name, text in files.items():
        path = directory / name
        path.write_text(text)
        written.append(path)
    return written
