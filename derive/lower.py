"""Lowering: a :class:`~.ir.Kernel` -> the data the ``kernels.py.j2`` template renders.

Per :class:`~.ir.Stage`, one ``sympy.cse`` over all its assignments (temporaries shared between
them, numbered ``_x0, _x1, ...`` across the kernel, canonical order so the output is
deterministic). Reciprocals used more than once are computed once (``1.0/x`` then products).

One CSE per stage, not per kernel, because a wider scope does not pay (measured on the generated
modules, 2026-12-01): reusing in later stages the temporaries and values earlier stages computed
(where the later code sees them) removed 0.4 % of the bytecode numba compiles (146,944 -> 146,421
instructions over all kernel modules; iterative_jacobian 55,864 -> 55,852), one CSE over each run
of consecutive stages of a derivative kernel 0.1 % more, and LLVM's value numbering already
computes such a repeated expression (``omega**2`` in two stages) once in the machine code. Per
stage the primal kernels' values stay what they were to the last bit.

The declaration is checked here, at generation time:

- every symbol an expression uses is an argument or the result of an earlier step
  (:class:`LoweringError` names the kernel, the step and the symbol);
- no name is defined twice in one scope, every :class:`~.ir.Switch` branch defines the same
  names, a :class:`~.ir.Call` passes exactly the callee's arguments and binds only its outputs;
- every output is defined by the end of the kernel.
"""

from __future__ import annotations

import hashlib
import keyword
import math
import re
from collections import Counter
from dataclasses import dataclass, field

import sympy as sp

from .ir import (
    MAX_NODES,
    MAX_SCALARS,
    Call,
    Directions,
    Guard,
    Iterate,
    Kernel,
    Layout,
    Load,
    Lookup,
    Nodes,
    Reduce,
    Stage,
    Store,
    Switch,
)
from .printer import to_code


class LoweringError(ValueError):
    """A kernel declaration that cannot be generated (names the kernel, the step and the cause)."""


def _names(expr) -> set[str]:
    return {s.name for s in sp.sympify(expr).free_symbols}


#: Names the template and the lowering use themselves: a declared name must not take one.
_GENERATED_NAME = re.compile(
    r"_(x\d+|c\d+|it\d+|last\d+|n\d+_\d+|o\d+_\d+|conv\d+|pk[in]?\d+|NAN\d+|T|j\d+|[aop]\d+|code|status|L[0-9a-f]{8})|STATUS_\w+"
)
_TEMPLATE_NAMES = frozenset(
    {"i", "out", "status", "math", "np", "njit", "carray", "NAN"}
    | {"stack", "fail", "finite", "load", "store", "node_arrays", "all_finite"}
)

#: The generated support module every kernel module imports (derive/templates/support.py.j2): stack
#: arrays, NaN-filling a failed row, storing a result tuple into a row.
SUPPORT_MODULE = "support"


def _check_name(name: str, where: str) -> None:
    if not name.isidentifier() or keyword.iskeyword(name):
        raise LoweringError(f"{where}: {name!r} is not a valid Python identifier")
    if _GENERATED_NAME.fullmatch(name) or name in _TEMPLATE_NAMES:
        raise LoweringError(f"{where}: {name!r} is reserved for the generated code")


@dataclass
class _Scope:
    frames: list[set[str]]

    def defined(self, name: str) -> bool:
        return any(name in f for f in self.frames)

    def all(self) -> set[str]:
        return set().union(*self.frames)

    def define(self, name: str, where: str) -> None:
        _check_name(name, where)
        if self.defined(name):
            raise LoweringError(f"{where}: {name!r} is already defined (names are assigned once)")
        self.frames[-1].add(name)


@dataclass
class _Ctx:
    kernel: Kernel
    scope: _Scope
    temps: int = 0
    calls: int = 0
    loops: int = 0
    ops: int = 0
    callees: set[tuple[str, str]] = field(default_factory=set)
    #: every kernel the code calls, of any module (derive/share.py)
    called: set[str] = field(default_factory=set)
    #: the status codes the kernel's code names (imported from generated/status.py)
    statuses: set[str] = field(default_factory=set)
    #: the direction array ``_T``: its rows (the largest used + 1) and directions (columns)
    rows: int = 0
    directions: int = 0
    n_dir_loops: int = 0
    #: whether the code uses generated/support.py (stack arrays, row stores)
    uses_support: bool = False
    #: node arrays the kernel writes (each on its stack, MAX_NODES long), in order of definition
    arrays: list = field(default_factory=list)
    #: what kind of value each name of a lookup table or node array is: "scalar" (a table's
    #: number), "vector" (a table's or a node array), "matrix" (a table's)
    shapes: dict = field(default_factory=dict)
    #: the module constants of the lookup tables: name -> (padded shape, values by code)
    tables: dict = field(default_factory=dict)
    #: the largest value of each scalar lookup table of whole numbers (a node count's bound)
    bounds: dict = field(default_factory=dict)
    node_loops: int = 0
    #: what each branch of a switch defined, for a later switch on the same selector in a scope
    #: the first one's is still open: (that scope, selector, code, names, the branch's scope)
    branches: list = field(default_factory=list)
    #: per open branch, the scopes of the earlier branches it continues
    aliases: list = field(default_factory=list)

    def push(self) -> None:
        self.scope.frames.append(set())

    def pop(self) -> set[str]:
        return self.scope.frames.pop()

    def where(self, what: str) -> str:
        return f"kernel {self.kernel.name}: {what}"

    def require(self, expr, what: str) -> None:
        missing = sorted(n for n in _names(expr) if not self.scope.defined(n))
        if missing:
            raise LoweringError(
                f"{self.where(what)} uses {', '.join(missing)}, which is neither an input nor the "
                "result of an earlier step"
            )


def _share_reciprocals(replacements, reduced, start: int):
    """Replace x**-n (x a symbol seen in two or more denominators) by r**n with r = 1/x computed once."""
    exprs = [e for _, e in replacements] + list(reduced)
    counts: Counter = Counter()
    for e in exprs:
        for p in sp.preorder_traversal(e):
            if isinstance(p, sp.Pow) and p.exp.is_Integer and p.exp < 0 and p.base.is_Symbol:
                counts[p.base] += 1
    bases = sorted((b for b, c in counts.items() if c >= 2), key=lambda s: s.name)
    if not bases:
        return replacements, reduced, start
    # A temporary CSE already made for 1/b is that reciprocal; the others get a new temporary.
    existing = {
        e.base: s for s, e in replacements if isinstance(e, sp.Pow) and e.exp == -1 and e.base in bases
    }
    replacements = [(s, e) for s, e in replacements if s not in existing.values()]
    recips = []
    subs = {}
    for b in bases:
        r = existing.get(b)
        if r is None:
            r = sp.Symbol(f"_x{start}", real=True)
            start += 1
        recips.append((b, r))
        subs[b] = r

    def swap(e):
        return e.replace(
            lambda p: isinstance(p, sp.Pow) and p.base in subs and p.exp.is_Integer and p.exp < 0,
            lambda p: subs[p.base] ** (-p.exp),
        )

    # A reciprocal is emitted right after its base is available: before the first temporary when the
    # base is an input or an earlier result, else right after the temporary that defines it.
    temp_names = [s for s, _ in replacements]
    out = []
    pending = [(b, r) for b, r in recips if b not in temp_names]
    out.extend((r, 1 / b) for b, r in pending)
    for s, e in replacements:
        out.append((s, swap(e)))
        out.extend((r, 1 / b) for b, r in recips if b == s)
    return out, [swap(e) for e in reduced], start


def _lower_stage(ctx: _Ctx, stage: Stage, idx: str) -> list[dict]:
    where = f"stage {idx}" + (f" ({stage.comment})" if stage.comment else "")
    names = [s.name for s, _ in stage.assignments]
    local: set[str] = set()
    for s, expr in stage.assignments:
        missing = sorted(n for n in _names(expr) if not ctx.scope.defined(n) and n not in local)
        if missing:
            raise LoweringError(
                f"{ctx.where(where)}: {s.name} uses {', '.join(missing)}, which is neither an input "
                "nor the result of an earlier step"
            )
        local.add(s.name)
    # CSE temporaries are emitted before the stage's named assignments, so an assignment that uses
    # an earlier one of the same stage gets it inlined (CSE then shares it again). With opaque names
    # each temporary comes just before the first assignment that needs it instead.
    opaque = set(stage.opaque)
    zero = dict.fromkeys(stage.zero, sp.S.Zero)
    exprs: list[sp.Basic] = []
    earlier: dict[str, sp.Basic] = {}
    for n, (_, expr) in zip(names, stage.assignments, strict=True):
        expr = sp.sympify(expr).xreplace(zero) if zero else sp.sympify(expr)
        inner = {s: earlier[s.name] for s in expr.free_symbols if s.name in earlier}
        exprs.append(expr.xreplace(inner) if inner else expr)
        if n not in opaque:
            earlier[n] = exprs[-1]
    replacements, reduced = sp.cse(
        exprs, symbols=sp.numbered_symbols("_x", start=ctx.temps), order="canonical"
    )
    start = ctx.temps + len(replacements)
    replacements, reduced, start = _share_reciprocals(replacements, reduced, start)
    ctx.temps = start
    ctx.ops += sum(sp.count_ops(e) for _, e in replacements) + sum(sp.count_ops(e) for e in reduced)
    nodes: list[dict] = []
    if stage.comment:
        nodes.append({"kind": "comment", "text": stage.comment})
    if not opaque:
        nodes += [{"kind": "assign", "name": str(s), "code": to_code(e)} for s, e in replacements]
        for n, e in zip(names, reduced, strict=True):
            ctx.scope.define(n, ctx.where(where))
            nodes.append({"kind": "assign", "name": n, "code": to_code(e)})
    else:
        temps = dict(replacements)
        emitted: set[sp.Symbol] = set()

        def emit(expr) -> None:
            for t in sorted(expr.free_symbols & temps.keys() - emitted, key=lambda t: int(t.name[2:])):
                emitted.add(t)
                emit(temps[t])
                nodes.append({"kind": "assign", "name": t.name, "code": to_code(temps[t])})

        for n, e in zip(names, reduced, strict=True):
            emit(e)
            ctx.scope.define(n, ctx.where(where))
            nodes.append({"kind": "assign", "name": n, "code": to_code(e)})
    for g in stage.guards:
        nodes.append(_guard(ctx, g, where))
    return nodes


def _guard(ctx: _Ctx, g: Guard, where: str) -> dict:
    if not ctx.kernel.status:
        raise LoweringError(ctx.where(f"{where} has a guard but the kernel returns no status"))
    ctx.require(g.condition, f"{where}, guard {g.status}")
    ctx.statuses.add(g.status)
    return {"kind": "guard", "code": to_code(g.condition), "status": g.status, "doc": g.doc}


@dataclass(frozen=True)
class Abi:
    """How a kernel is called (:func:`abi`)."""

    #: a role kernel: ``kernel(x, p, out) -> status`` (:class:`~.ir.Layout`)
    layout: Layout | None
    #: more than :data:`~.ir.MAX_SCALARS` arguments: one array ``_a`` holds them, in order
    args_array: bool
    #: its outputs go into an array the caller gives (a role kernel, or more than MAX_SCALARS
    #: values with the status), and it returns the status
    out_array: bool


def abi(kernel: Kernel) -> Abi:
    """A role kernel takes its layouts; any other kernel takes up to :data:`~.ir.MAX_SCALARS`
    scalar arguments, else one array of them, and returns a tuple of up to MAX_SCALARS values (its
    outputs, then its status), else writes its outputs into an array argument ``out`` and returns
    the status."""
    if kernel.layout is not None:
        if not kernel.status:
            raise LoweringError(f"kernel {kernel.name}: a role kernel (a layout) returns a status")
        return Abi(kernel.layout, False, True)
    n_out = len(kernel.output_names) + (1 if kernel.status else 0)
    if n_out > MAX_SCALARS and not kernel.status:
        raise LoweringError(f"kernel {kernel.name}: {n_out} outputs without a status to return")
    return Abi(None, len(kernel.args) > MAX_SCALARS, n_out > MAX_SCALARS)


def _stack(var: str, n: int) -> str:
    """A float64 array of ``n`` on the kernel's stack (generated/support.py)."""
    return f"{var} = carray(stack({n}), {n})"


def _put(var: str, codes: list[str]) -> str:
    """``codes`` into ``var[0], var[1], ...``: one call of ``support.store`` (numba lowers a
    subscript store as a call of its own; a helper looping over a tuple compiled once per tuple
    length)."""
    return f"store({var}, ({', '.join(codes)},))"


#: A role kernel with at most this many output values checks them one by one before its store
#: (a branch each, in registers); one with more stores its row and loops over it (support.finite).
FINITE_CHAIN = 24


def _finite_chain(codes: list[str], limit: int | None = FINITE_CHAIN) -> str | None:
    """``all_finite((c0, c1, ...))`` over the distinct codes that are not numbers (support.py: one
    call), or None when there are more than ``limit`` of them (None: no limit)."""
    names = list(dict.fromkeys(c for c in codes if not re.fullmatch(r"-?[0-9.]+(e-?[0-9]+)?", c)))
    if limit is not None and len(names) > limit:
        return None
    return f"all_finite(({', '.join(names)},))" if names else "True"


def _passes_p(ctx: _Ctx, call: Call) -> bool:
    """Whether a call of a role kernel passes the caller's own parameter record ``p``: both have the
    same record and every field the callee reads from it is the caller's argument of that name."""
    caller, callee = ctx.kernel.layout, call.kernel.layout
    if caller is None or callee.p != caller.p:
        return False
    for a in call.kernel.arg_names:
        if a in callee.x:
            continue
        expr = sp.sympify(call.args[a])
        if not (isinstance(expr, sp.Symbol) and expr.name == a and a in caller.p and a not in caller.x):
            return False
    return True


def _lower_call(ctx: _Ctx, call: Call, idx: str) -> list[dict]:
    callee = call.kernel
    where = f"step {idx} (call {callee.name})"
    expected, given = set(callee.arg_names), set(call.args)
    if expected != given:
        raise LoweringError(
            ctx.where(
                f"{where}: arguments must be exactly the callee's; missing {sorted(expected - given)}, "
                f"unknown {sorted(given - expected)}"
            )
        )
    unknown = sorted(set(call.bind) - set(callee.output_names))
    if unknown:
        raise LoweringError(ctx.where(f"{where}: {callee.name} has no output(s) {unknown}"))
    if callee.status and not ctx.kernel.status:
        raise LoweringError(ctx.where(f"{where}: the callee returns a status, the caller cannot"))
    for name in callee.arg_names:
        ctx.require(call.args[name], f"{where}, argument {name}")
    ctx.called.add(callee.name)
    if callee.module != ctx.kernel.module:
        ctx.callees.add((callee.module, callee.name))
    n = ctx.calls
    ctx.calls += 1
    how = abi(callee)
    setup: list[str] = []
    if how.layout is not None:
        x, o = f"_x{n}", f"_o{n}"
        setup += [_stack(x, len(how.layout.x)), _put(x, [to_code(call.args[a]) for a in how.layout.x])]
        if _passes_p(ctx, call):
            p = "p"
        else:
            p = f"_p{n}"
            codes = [to_code(call.args[f]) if f in call.args else "NAN" for f in how.layout.p]
            setup += [_stack(p, len(codes)), _put(p, codes)] if codes else [_stack(p, 1)]
        args = [x, p]
    elif how.args_array:
        a = f"_a{n}"
        setup += [
            _stack(a, len(callee.arg_names)),
            _put(a, [to_code(call.args[a_]) for a_ in callee.arg_names]),
        ]
        args = [a]
    else:
        args = [to_code(call.args[a_]) for a_ in callee.arg_names]
    ctx.uses_support |= bool(setup)
    nodes = [{"kind": "comment", "text": call.comment}] if call.comment else []
    outs = callee.output_names
    if call.tail:
        if call.bind or outs != ctx.kernel.output_names or callee.status != ctx.kernel.status:
            raise LoweringError(
                ctx.where(f"{where}: a tail call returns the callee's result as the caller's")
            )
        if how.out_array != abi(ctx.kernel).out_array:
            raise LoweringError(ctx.where(f"{where}: a tail call's callee returns as its caller does"))
        expr = f"{callee.name}({', '.join(args + (['out'] if how.out_array else []))})"
        return nodes + [{"kind": "tail", "setup": setup, "expr": expr}]
    var = f"_c{n}"
    if how.out_array:
        o = f"_o{n}"
        setup.append(_stack(o, len(outs)))
        args.append(o)
        status = var
        source = {name: f"{o}[{i}]" for i, name in enumerate(outs)}
    else:
        single = not callee.status and len(outs) == 1
        status = f"{var}[{len(outs)}]" if callee.status else None
        source = {name: var if single else f"{var}[{i}]" for i, name in enumerate(outs)}
    binds = []
    for out_name, local in call.bind.items():
        ctx.scope.define(local, ctx.where(where))
        binds.append({"name": local, "code": source[out_name]})
    nodes.append(
        {
            "kind": "call",
            "setup": setup,
            "var": var,
            "expr": f"{callee.name}({', '.join(args)})",
            "status": status,
            "binds": binds,
            "out": o if how.out_array else None,
            "load": None,
        }
    )
    return nodes


def _lower_iterate(ctx: _Ctx, it: Iterate, idx: str) -> list[dict]:
    where = f"step {idx} (iteration)"
    for s, init in (*it.state, *((c[0], c[1]) for c in it.carry)):
        ctx.require(init, f"{where}, initial value of {s.name}")
    for e, what in ((it.max_iter, "max_iter"), (it.tol, "tol"), *((s, "a scale") for s in it.scales)):
        ctx.require(e, f"{where}, {what}")
    n = ctx.loops
    ctx.loops += 1
    state = []
    for s, init in (*it.state, *((c[0], c[1]) for c in it.carry)):
        ctx.scope.define(s.name, ctx.where(where))
        state.append({"name": s.name, "code": to_code(init)})
    ctx.scope.define(it.count.name, ctx.where(where))
    arrays = []
    for a, init, upd, scale in it.arrays + tuple((*c, None) for c in it.array_carry):
        _require_array(ctx, init, f"{where}, initial array of {a}")
        ctx.scope.define(a, ctx.where(where))
        _new_array(ctx, a)
        arrays.append(
            {"name": a, "init": init, "next": upd, "scale": None if scale is None else to_code(scale)}
        )
    if arrays:
        ctx.require(it.nodes, f"{where}, node count")
    ctx.push()
    evaluate = _lower_steps(ctx, it.evaluate, f"{idx}.evaluate.")
    evaluated = set(ctx.scope.frames[-1])
    body = _lower_steps(ctx, it.body, f"{idx}.")
    updates = []
    for k, ((s, _), e, scale) in enumerate(zip(it.state, it.update, it.scales, strict=True)):
        ctx.require(e, f"{where}, update of {s.name}")
        updates.append(
            {"tmp": f"_n{n}_{k}", "name": s.name, "code": to_code(e), "scale": to_code(scale), "check": True}
        )
    for k, (s, _, e) in enumerate(it.carry, start=len(it.state)):
        ctx.require(e, f"{where}, update of {s.name}")
        updates.append({"tmp": f"_n{n}_{k}", "name": s.name, "code": to_code(e), "scale": "", "check": False})
    loop_names = {s.name for s, _ in it.state} | {c[0].name for c in it.carry}
    for u, e in zip(updates, list(it.update) + [c[2] for c in it.carry], strict=True):
        # a packed loop's new value that is a number or a variable of the pass goes in as it is
        e = sp.sympify(e)
        u["direct"] = bool(it.carry) and (e.is_Number or (e.is_Symbol and e.name not in loop_names))
        if u["direct"]:
            u["tmp"] = u["code"]
    for arr in arrays:
        _require_array(ctx, arr["next"], f"{where}, update array of {arr['name']}")
    ctx.pop()
    # what the loop evaluates at every iterate stays visible, at the iterate it stops at
    ctx.scope.frames[-1] |= evaluated
    if it.fail_status is not None and not ctx.kernel.status:
        raise LoweringError(ctx.where(f"{where}: a failing iteration needs a status output"))
    if it.fail_status is not None:
        ctx.statuses.add(it.fail_status)
    nodes = [{"kind": "comment", "text": it.comment}] if it.comment else []
    nodes.append(
        {
            "kind": "loop",
            "packed": bool(it.carry),
            "pack": f"_pk{n}",
            "pack_init": f"_pki{n}",
            "pack_next": f"_pkn{n}",
            "it": f"_it{n}",
            "last": f"_last{n}",
            "max_iter": to_code(it.max_iter),
            "state": state,
            "count": it.count.name,
            "evaluate": evaluate,
            "body": body,
            "updates": updates,
            "conv": f"_conv{n}",
            "tol": to_code(it.tol),
            "fail_status": it.fail_status,
            "arrays": arrays,
            "nodes": to_code(it.nodes) if arrays else "",
            "bound": _bound(ctx, to_code(it.nodes)) if arrays else None,
            "a": _node_index(ctx) if arrays else "",
        }
    )
    return nodes


def _lower_switch(ctx: _Ctx, sw: Switch, idx: str) -> list[dict]:
    where = f"step {idx} (switch on {sw.selector.name})"
    ctx.require(sw.selector, where)
    if not ctx.kernel.status:
        raise LoweringError(ctx.where(f"{where}: a switch needs a status output (unknown codes)"))
    ctx.statuses.add("INVALID_INPUT")
    # Every branch must define the same public names; a name starting with "_" may be defined by
    # some branches only (a branch-local helper) and is visible after the switch only if all do.
    # A branch also sees what the same branch of an earlier switch on the same selector defined, if
    # that switch's scope is still open (an option is assigned once: the same branch ran there):
    # the tangent code of a branch, run per direction, reads its partial derivatives (tangent.py).
    # (the earlier branch's scope then counts as open in this one, for the switches nested in both).
    enclosing = ctx.scope.frames[-1]
    cases = []
    branch_names: list[set[str]] = []
    for value, steps in sw.cases:
        ctx.push()
        seen: set[str] = set()
        aliases = []
        for scope, selector, code, names, frame in ctx.branches:
            if selector == sw.selector.name and code == value and _is_open(ctx, scope):
                seen |= names - ctx.scope.all()
                aliases.append(frame)
        ctx.scope.frames[-1].update(seen)
        ctx.aliases.append(aliases)
        nodes = _lower_steps(ctx, steps, f"{idx}.{value}.")
        ctx.aliases.pop()
        frame = ctx.pop()
        names = frame - seen
        ctx.branches.append((enclosing, sw.selector.name, value, names, frame))
        branch_names.append(names)
        cases.append({"value": to_code(sp.Integer(value)), "body": nodes})
    publics = [{n for n in names if not n.startswith("_")} for names in branch_names]
    for value_names, (value, _) in zip(publics, sw.cases, strict=True):
        if value_names != publics[0]:
            raise LoweringError(
                ctx.where(
                    f"{where}: branch {value} defines {sorted(value_names)}, another {sorted(publics[0])}"
                )
            )
    for name in sorted(set.intersection(*branch_names) if branch_names else ()):
        ctx.scope.define(name, ctx.where(where))
    nodes = [{"kind": "comment", "text": sw.comment}] if sw.comment else []
    nodes.append({"kind": "switch", "selector": to_code(sw.selector), "cases": cases})
    return nodes


def _is_open(ctx: _Ctx, scope: set) -> bool:
    """Whether ``scope`` is open: one of the current scopes, or the earlier branch a current branch
    continues (:func:`_lower_switch`)."""
    return any(f is scope for f in ctx.scope.frames) or any(f is scope for a in ctx.aliases for f in a)


def _directions(ctx: _Ctx, n: int, row: int, where: str) -> None:
    if ctx.directions and ctx.directions != n:
        raise LoweringError(ctx.where(f"{where}: {n} directions, the kernel has {ctx.directions}"))
    ctx.directions = n
    ctx.rows = max(ctx.rows, row + 1)
    ctx.uses_support = True  # the direction array is on the kernel's stack


def _lower_store(ctx: _Ctx, st: Store, idx: str) -> list[dict]:
    where = f"step {idx} (store in row {st.row})"
    _directions(ctx, len(st.values), st.row, where)
    for e in st.values:
        ctx.require(e, where)
    return [{"kind": "store", "row": st.row, "codes": [to_code(e) for e in st.values]}]


def _lower_load(ctx: _Ctx, ld: Load, idx: str) -> list[dict]:
    where = f"step {idx} (load of row {ld.row})"
    _directions(ctx, len(ld.names), ld.row, where)
    for s in ld.names:
        ctx.scope.define(s.name, ctx.where(where))
    return [{"kind": "load", "row": ld.row, "names": [s.name for s in ld.names]}]


def _lower_directions(ctx: _Ctx, d: Directions, idx: str) -> list[dict]:
    where = f"step {idx} (per direction)"
    for _, row in (*d.reads, *d.writes):
        _directions(ctx, d.n, row, where)
    ctx.push()
    for s, _ in d.reads:
        ctx.scope.define(s.name, ctx.where(where))
    body = _lower_steps(ctx, d.steps, f"{idx}.")
    for e, row in d.writes:
        ctx.require(e, f"{where}, write of row {row}")
    ctx.pop()
    j = f"_j{ctx.n_dir_loops}"
    ctx.n_dir_loops += 1
    nodes = [{"kind": "comment", "text": d.comment}] if d.comment else []
    nodes.append(
        {
            "kind": "directions",
            "j": j,
            "n": d.n,
            "reads": [{"name": s.name, "row": row} for s, row in d.reads],
            "body": body,
            "writes": [{"code": to_code(e), "row": row} for e, row in d.writes],
        }
    )
    return nodes


def _node_index(ctx: _Ctx) -> str:
    """A fresh loop variable over nodes."""
    ctx.node_loops += 1
    return f"_j{ctx.node_loops + 999}"


def _new_array(ctx: _Ctx, name: str) -> None:
    """A node array the kernel writes: on its stack (:data:`~.ir.MAX_NODES` entries)."""
    if name not in ctx.arrays:
        ctx.arrays.append(name)
    ctx.shapes[name] = "vector"
    ctx.uses_support = True


def _require_array(ctx: _Ctx, name: str, where: str, shape: str = "vector") -> None:
    if not ctx.scope.defined(name):
        raise LoweringError(ctx.where(f"{where}: {name!r} is not defined before"))
    if ctx.shapes.get(name) != shape:
        raise LoweringError(ctx.where(f"{where}: {name!r} is not a node {shape}"))


def _padded(values, code: int, shape: str):
    """A table's values as nested lists of floats (a vector or matrix padded with NaN)."""
    if shape == "scalar":
        return float(values)
    if shape == "vector":
        return [float(v) for v in values] + [math.nan] * (MAX_NODES - len(values))
    rows = [[float(v) for v in row] + [math.nan] * (MAX_NODES - len(row)) for row in values]
    return rows + [[math.nan] * MAX_NODES] * (MAX_NODES - len(rows))


def filled(values: list) -> list:
    """A lookup table's values by code (:func:`lower`'s ``tables``) with every code that has no table
    (None) as NaN in the tables' shape: what each target writes as the module constant."""
    first = next(v for v in values if v is not None)

    def nan_like(x):
        return [nan_like(e) for e in x] if isinstance(x, list) else math.nan

    return [v if v is not None else nan_like(first) for v in values]


def _lower_lookup(ctx: _Ctx, lk: Lookup, idx: str) -> list[dict]:
    where = f"step {idx} (lookup on {to_code(lk.selector)})"
    ctx.require(lk.selector, where)
    ctx.statuses.add("INVALID_INPUT")
    codes = sorted({c for _, tables in lk.tables for c, _ in tables})
    binds = []
    for name, tables in lk.tables:
        by_code = dict(tables)
        if sorted(by_code) != codes:
            raise LoweringError(ctx.where(f"{where}: table {name} lacks a code of {codes}"))
        first = by_code[codes[0]]
        shape = (
            "scalar"
            if not isinstance(first, tuple)
            else "matrix"
            if isinstance(first[0], tuple)
            else "vector"
        )
        if shape != "scalar" and any(len(v) > MAX_NODES for v in by_code.values()):
            raise LoweringError(ctx.where(f"{where}: table {name} is longer than {MAX_NODES} nodes"))
        values = [_padded(by_code[c], c, shape) if c in by_code else None for c in range(codes[-1] + 1)]
        digest = hashlib.sha256(repr((shape, values)).encode()).hexdigest()[:8]
        const = f"_L{digest}"
        ctx.tables[const] = values
        ctx.scope.define(name, ctx.where(where))
        ctx.shapes[name] = shape
        if shape == "scalar" and all(float(v).is_integer() and v >= 0 for v in by_code.values()):
            ctx.bounds[name] = int(max(by_code.values()))
        binds.append({"name": name, "const": const})
    nodes = [{"kind": "comment", "text": lk.comment}] if lk.comment else []
    valid = " or ".join(f"_code == {c}" for c in codes)
    nodes.append({"kind": "lookup", "selector": to_code(lk.selector), "valid": valid, "binds": binds})
    return nodes


def _bound(ctx: _Ctx, count: str) -> int | None:
    """The trip count of a node loop over ``count`` nodes (the largest count of the lookup that binds
    it; the loop stops at ``count``), or None: a loop to ``count`` (:attr:`Kernel.unroll_nodes`)."""
    bound = ctx.bounds.get(count) if ctx.kernel.unroll_nodes else None
    return bound if bound is not None and bound <= MAX_NODES else None


def _lower_nodes(ctx: _Ctx, nd: Nodes, idx: str) -> list[dict]:
    where = f"step {idx} (node loop)"
    ctx.require(nd.count, f"{where}, node count")
    for _, array in nd.reads:
        if ctx.shapes.get(array) != "vector":
            raise LoweringError(ctx.where(f"{where}: reads {array!r}, not a node vector"))
    for _, matrix, array in nd.sums:
        _require_array(ctx, matrix, where, "matrix")
        _require_array(ctx, array, where)
    j = _node_index(ctx)
    ctx.push()
    for local, _ in nd.reads:
        ctx.scope.define(local.name, ctx.where(where))
    for local, _, _ in nd.sums:
        ctx.scope.define(local.name, ctx.where(where))
    body = _lower_steps(ctx, nd.steps, f"{idx}.")
    for e, _ in nd.writes:
        ctx.require(e, f"{where}, a write")
    writes = [{"code": to_code(e), "array": a} for e, a in nd.writes]
    ctx.pop()
    for _, array in nd.writes:
        ctx.scope.define(array, ctx.where(where))
        _new_array(ctx, array)
    k = _node_index(ctx)
    nodes = [{"kind": "comment", "text": nd.comment}] if nd.comment else []
    nodes.append(
        {
            "kind": "nodes",
            "j": j,
            "k": k,
            "count": to_code(nd.count),
            "bound": _bound(ctx, to_code(nd.count)),
            "reads": [{"name": s.name, "array": a} for s, a in nd.reads],
            "sums": [{"name": s.name, "matrix": m, "array": a} for s, m, a in nd.sums],
            "body": body,
            "writes": writes,
        }
    )
    return nodes


def _lower_reduce(ctx: _Ctx, rd: Reduce, idx: str) -> list[dict]:
    where = f"step {idx} (sum over nodes of {rd.array})"
    ctx.require(rd.count, f"{where}, node count")
    _require_array(ctx, rd.array, where)
    if rd.weights is not None:
        _require_array(ctx, rd.weights, where)
    ctx.scope.define(rd.name.name, ctx.where(where))
    term = f"{rd.weights}[{{k}}]*{rd.array}[{{k}}]" if rd.weights else f"{rd.array}[{{k}}]"
    k = _node_index(ctx)
    nodes = [{"kind": "comment", "text": rd.comment}] if rd.comment else []
    sums = [{"name": rd.name.name, "term": term.format(k=k)}]
    count = to_code(rd.count)
    nodes.append({"kind": "reduce", "k": k, "count": count, "bound": _bound(ctx, count), "sums": sums})
    return nodes


def _fuse_reduces(nodes: list[dict]) -> list[dict]:
    """Consecutive sums over the same nodes in one loop (a derivative kernel's sums come one per
    direction: one loop instead of seven keeps numba's and LLVM's work per kernel down). A sum joins
    the loop before it unless it reads one of that loop's sums."""
    out: list[dict] = []
    for n in nodes:
        prev = out[-1] if out else None
        fusable = prev is not None and prev["kind"] == n["kind"] == "reduce" and prev["count"] == n["count"]
        if fusable:
            names = {sm["name"] for sm in prev["sums"]}
            k = re.compile(rf"\b{n['k']}\b")
            renamed = [{"name": sm["name"], "term": k.sub(prev["k"], sm["term"])} for sm in n["sums"]]
            if not any(names & set(_WORD.findall(sm["term"])) for sm in renamed):
                prev["sums"] = prev["sums"] + renamed
                continue
        out.append(n)
    return out


def _compact_rows(nodes: list[dict]) -> int:
    """Renumber the direction array's rows the kernel uses 0, 1, ... in order of first use (a
    derivative kernel's rows are numbered across the kernels outlined from it); their number."""
    order: dict[int, int] = {}

    def walk(ns) -> None:
        for n in ns:
            if n["kind"] in ("store", "load"):
                n["row"] = order.setdefault(n["row"], len(order))
            elif n["kind"] == "directions":
                for rw in n["reads"] + n["writes"]:
                    rw["row"] = order.setdefault(rw["row"], len(order))
                walk(n["body"])
            elif n["kind"] == "loop":
                walk(n["evaluate"])
                walk(n["body"])
            elif n["kind"] == "switch":
                for c in n["cases"]:
                    walk(c["body"])

    walk(nodes)
    return len(order)


def _lower_steps(ctx: _Ctx, steps, prefix: str = "") -> list[dict]:
    nodes: list[dict] = []
    for i, step in enumerate(steps):
        idx = f"{prefix}{i}"
        if isinstance(step, Stage):
            nodes += _lower_stage(ctx, step, idx)
        elif isinstance(step, Call):
            nodes += _lower_call(ctx, step, idx)
        elif isinstance(step, Iterate):
            nodes += _lower_iterate(ctx, step, idx)
        elif isinstance(step, Switch):
            nodes += _lower_switch(ctx, step, idx)
        elif isinstance(step, Store):
            nodes += _lower_store(ctx, step, idx)
        elif isinstance(step, Load):
            nodes += _lower_load(ctx, step, idx)
        elif isinstance(step, Directions):
            nodes += _lower_directions(ctx, step, idx)
        elif isinstance(step, Lookup):
            nodes += _lower_lookup(ctx, step, idx)
        elif isinstance(step, Nodes):
            nodes += _lower_nodes(ctx, step, idx)
        elif isinstance(step, Reduce):
            nodes += _lower_reduce(ctx, step, idx)
        else:
            raise LoweringError(ctx.where(f"step {idx}: unknown step type {type(step).__name__}"))
    return _fuse_reduces(nodes)


def _unpack(names: list[str], array: str, order) -> str:
    """``(a, b,) = load(x, 0, 3)``: the names from their positions in ``order``, the fields of
    ``array``, read in one call of ``support.load``."""
    at = {n: i for i, n in enumerate(order)}
    return f"({', '.join(names)},) = load({array}, {', '.join(str(at[n]) for n in names)})"


_SOURCE = re.compile(r"(_o\d+\[\d+\]|-?\d+\.\d*(e[-+]?\d+)?)$")
_WORD = re.compile(r"[A-Za-z_]\w*")


def _strings(node, skip) -> list[str]:
    """Every code string in a lowered node tree, except the entries in ``skip`` (by identity) and
    the argument lists of calls (``setup``: where :func:`_forward` substitutes)."""
    if isinstance(node, str):
        return [node]
    if isinstance(node, list):
        return [t for n in node for t in _strings(n, skip)]
    if isinstance(node, dict):
        if id(node) in skip:
            return []
        return [t for k, v in node.items() if k != "setup" for t in _strings(v, skip)]
    return []


_OUT_READ = re.compile(r"\b(_o\d+)\[(\d+)\]")


def _walk(node):
    """Every value of a lowered node tree (its dicts, lists and strings), at any depth, in order."""
    yield node
    if isinstance(node, (list, dict)):
        for v in node.values() if isinstance(node, dict) else node:
            yield from _walk(v)


def _rewrite(node, sub):
    """``node`` (a lowered node tree) with ``sub`` applied to every string in it."""
    if isinstance(node, str):
        return sub(node)
    if isinstance(node, list):
        return [_rewrite(n, sub) for n in node]
    if isinstance(node, dict):
        return {k: _rewrite(v, sub) for k, v in node.items()}
    return node


def _load_outputs(body: list[dict], forward: dict[str, str]) -> dict[str, str]:
    """Every read of a callee's out array (``_o1[7]``: a bind, or a value :func:`_forward` passed
    on) from one ``load`` right after its call (``(t_bottom, _o1_7,) = load(_o1, 0, 7)``, the
    binds' own names where they have one): numba lowers a subscript as a call of its own. Rewrites
    ``body`` in place; returns ``forward`` with its reads renamed."""
    reads: dict[str, set[int]] = {}
    for t in [*(v for v in _walk(body) if isinstance(v, str)), *forward.values()]:
        for m in _OUT_READ.finditer(t):
            reads.setdefault(m.group(1), set()).add(int(m.group(2)))
    name: dict[str, str] = {}
    for n in _walk(body):
        o = n.get("out") if isinstance(n, dict) and n.get("kind") == "call" else None
        if o not in reads:
            continue
        for b in n["binds"]:
            name.setdefault(b["code"], b["name"])
        at = sorted(reads[o])
        names = [name.setdefault(f"{o}[{i}]", f"{o}_{i}") for i in at]
        n["load"] = f"({', '.join(names)},) = load({o}, {', '.join(map(str, at))})"
        n["binds"] = [b for b in n["binds"] if name[b["code"]] != b["name"]]
    if not name:
        return forward

    def sub(text: str) -> str:
        return _OUT_READ.sub(lambda m: name[m.group(0)], text)

    body[:] = _rewrite(body, sub)
    return {k: sub(v) for k, v in forward.items()}


def _forward(body: list[dict]) -> dict[str, str]:
    """Forward the values a kernel only passes on: a top-level call's output read from its out
    array (``_o1[7]``), or a constant assignment, that nothing but later calls' argument lists and
    the kernel's outputs use is not named; those lists and the outputs read it where it is. The
    source arrays are written once, by their call, so the read gives the same value anywhere
    after it. Returns the outputs' codes by name (the others stay their names)."""
    defs: dict[str, tuple[dict, dict | None]] = {}
    for n in body:
        if n["kind"] == "call":
            for b in n["binds"]:
                if _SOURCE.match(b["code"]):
                    defs[b["name"]] = (n, b)
        elif n["kind"] == "assign" and (_SOURCE.match(n["code"]) or n["code"] in defs):
            # (a copy of a forwarded value, e.g. a derivative taken from a callee's row as it is)
            defs[n["name"]] = (n, None)
    if not defs:
        return {}
    skip = {id(b if b is not None else n) for n, b in defs.values()}
    used = Counter(w for t in _strings(body, skip) for w in _WORD.findall(t))
    forward = {name: (b or n)["code"] for name, (n, b) in defs.items() if not used[name]}
    # a copy of a copy reads the source
    for name, code in forward.items():
        while code in forward:
            code = forward[code]
        forward[name] = code
    # (a copy of a value kept by name stays: only sources forward)
    forward = {name: code for name, code in forward.items() if code not in defs}
    if not forward:
        return {}
    word = re.compile(r"\b(" + "|".join(map(re.escape, sorted(forward))) + r")\b")

    def sub(text: str) -> str:
        return word.sub(lambda m: forward[m.group(1)], text)

    def walk(nodes: list[dict]) -> list[dict]:
        kept = []
        for n in nodes:
            if n["kind"] == "assign" and n["name"] in forward and any(n is d[0] for d in defs.values()):
                continue
            if n["kind"] == "assign" and n["code"] in forward:
                n["code"] = forward[n["code"]]  # a copy kept, of a value forwarded
            if "setup" in n:
                n["setup"] = [sub(line) for line in n["setup"]]
            if n["kind"] == "call":
                n["binds"] = [b for b in n["binds"] if b["name"] not in forward]
            for key in ("evaluate", "body"):
                if key in n:
                    n[key] = walk(n[key])
            for c in n.get("cases", ()):
                c["body"] = walk(c["body"])
            kept.append(n)
        # a comment whose statements all went stays out too
        return [
            n
            for i, n in enumerate(kept)
            if n["kind"] != "comment" or (i + 1 < len(kept) and kept[i + 1]["kind"] != "comment")
        ]

    body[:] = walk(body)
    return forward


def lower(kernel: Kernel) -> dict:
    """Template data for one kernel (signature, docstring, nested statement nodes, returns)."""
    names = kernel.arg_names
    for n in names:
        _check_name(n, f"kernel {kernel.name}: argument")
    dup = [n for n, c in Counter(names).items() if c > 1]
    if dup:
        raise LoweringError(f"kernel {kernel.name}: duplicate argument(s) {dup}")
    if kernel.layout is not None:
        from .outline import defined

        taken = sorted((set(names) | defined(kernel.steps)) & {"x", "p"})
        if taken:
            raise LoweringError(
                f"kernel {kernel.name}: {taken} name a role kernel's layouts (x, p): rename them"
            )
    ctx = _Ctx(kernel, _Scope([set(names)]))
    input_guard = None
    if kernel.check_inputs:
        if not kernel.status:
            raise LoweringError(f"kernel {kernel.name}: input checks need a status output")
        checked = [n for n in names if n not in kernel.unchecked]
        conds = [_finite_chain(checked, None)] if checked else []
        conds += [f"({to_code(a.domain)})" for a in kernel.args if a.domain is not None]
        for a in kernel.args:
            if a.domain is not None:
                ctx.require(a.domain, f"domain of argument {a.name}")
        # one expression, no short-circuit: numba makes a block of every operand of ``and``, and
        # a block costs compile time (inlining copies every block with the function's scope)
        # (every operand a call or parenthesized: ``&`` binds tighter than a comparison)
        input_guard = " & ".join(conds)
        ctx.statuses.add("INVALID_INPUT")
        ctx.uses_support = True  # support.all_finite
    body = _lower_steps(ctx, kernel.steps)
    forward = _load_outputs(body, _forward(body))
    if ctx.rows:
        ctx.rows = _compact_rows(body)
    tails = [i for i, s in enumerate(kernel.steps) if isinstance(s, Call) and s.tail]
    if tails and tails != [len(kernel.steps) - 1]:
        raise LoweringError(f"kernel {kernel.name}: a tail call must be the last step")
    outputs = kernel.outputs.fields()
    missing = [] if tails else [f.name for f in outputs if not ctx.scope.defined(f.name)]
    if missing:
        raise LoweringError(f"kernel {kernel.name}: output(s) {missing} are never defined")
    dup_out = [n for n, c in Counter(f.name for f in outputs).items() if c > 1]
    if dup_out:
        raise LoweringError(f"kernel {kernel.name}: duplicate output(s) {dup_out}")
    how = abi(kernel)
    if how.layout is not None:
        # every role kernel checks its whole row (a Jacobian's derivatives too)
        ctx.statuses.add("NUMERICAL_RANGE")
        ctx.uses_support = True
    if how.out_array:
        ctx.uses_support = True
    if kernel.status:
        ctx.statuses.add("OK")
        if kernel.check_outputs:
            ctx.statuses.add("NUMERICAL_RANGE")
            ctx.uses_support = True  # support.all_finite
    docs = [{"name": f.name, "doc": f.doc + (f" [{f.unit}]" if f.unit else "")} for f in outputs]
    if kernel.doc_returns:
        docs = [{"name": n, "doc": d} for n, d in kernel.doc_returns]
    if how.layout is not None:
        params = ["x", "p", "out"]
        prologue = [_unpack([a for a in how.layout.x], "x", how.layout.x)]
        from_p = [a for a in names if a not in how.layout.x]
        if from_p:
            prologue.append(_unpack(from_p, "p", how.layout.p))
    elif how.args_array:
        params = ["_a"] + (["out"] if how.out_array else [])
        prologue = [_unpack(list(names), "_a", names)]
        ctx.uses_support = True
    else:
        params = list(names) + (["out"] if how.out_array else [])
        prologue = []
    return {
        "name": kernel.name,
        "summary": kernel.summary,
        "equations": ", ".join(kernel.equations),
        "notes": kernel.notes,
        "args": [{"name": a.name, "doc": a.doc} for a in kernel.args],
        "params": ", ".join(params),
        "prologue": prologue,
        "layout": None if how.layout is None else {"x": list(how.layout.x), "p": list(how.layout.p)},
        "out_array": how.out_array,
        "support": ctx.uses_support,
        "doc_args": kernel.doc_args,
        "outputs": [
            {"name": f.name, "code": forward.get(f.name, f.name), "checked": f.name not in kernel.unchecked}
            for f in outputs
        ],
        "partial_check": any(f.name in kernel.unchecked for f in outputs),
        "returns": docs,
        "n_out": len(outputs),
        "store": _put("out", [forward.get(f.name, f.name) for f in outputs]),
        # a role kernel checks its whole row (a chain if short, else support.finite); another kernel
        # its checked outputs
        "finite_chain": None
        if tails
        else _finite_chain([forward.get(f.name, f.name) for f in outputs])
        if how.layout is not None
        else _finite_chain(
            [forward.get(f.name, f.name) for f in outputs if f.name not in kernel.unchecked], None
        ),
        "input_guard": input_guard,
        "body": body,
        "status": kernel.status,
        "check_outputs": kernel.check_outputs,
        "inline": kernel.inline,
        "inline_rows": kernel.inline_rows,
        "tail": bool(tails),
        "ops": int(ctx.ops),
        "callees": sorted(ctx.callees),
        "called": sorted(ctx.called),
        # set by derive/share.py: the shared body an entry point runs and the callees it passes; the
        # kernels a shared body serves and its callee arguments
        "entry_of": None,
        "passes": [],
        "shared_by": [],
        "shared_names": "",
        "shared_args": [],
        "shared_what": "",
        "statuses": sorted(ctx.statuses),
        "rows": ctx.rows,
        "directions": ctx.directions,
        "arrays": list(ctx.arrays),
        "max_nodes": MAX_NODES,
        "tables": dict(ctx.tables),
    }
