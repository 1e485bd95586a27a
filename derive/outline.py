"""Outlining: a switch branch that holds a loop becomes a kernel of its own, called in place; and
pruning: the assignments, and the rows of the direction array, nothing uses are dropped. Used for
the derivative kernels (:mod:`.tangent`); the maps' own kernels are left as declared.

Why: numba's SSA reconstruction rewrites the whole function once per variable that is assigned
more than once or used where its one assignment does not dominate (a loop's variables, what a
branch defines): a cost of (such variables) x (statements of the function). A derivative kernel's
loops carry a tangent per state variable and direction (the compression half of Schwind and
Koditschek's iteration: 13 values x 7), and its branches define a tangent per output and direction,
so one function holding the five node-count branches, each a loop, compiled in 300 s. Now:

- a loop's tangents are rows of the direction array (the loops whose steps are stages, calls and
  switches of them, derive/tangent.py) or, carried variables, one tuple unpacked at the top of every pass
  (derive/lower.py, the packed loop), and its body is not outlined: a loop body outlined into a
  kernel of its own passed all its values and tangents through the call's arguments and result
  tuple every pass (about 200 for the six-node half), and every outlined level makes LLVM optimize
  and compile the kernels below it once more;
- a switch whose branches hold a loop is outlined (each branch a kernel returning the names used
  after the switch), so the variables its branches define and use after their loops stay in small
  functions.

Measured (iterative_jacobian.py, first call of the iterative apex-return Jacobian): with the loop
bodies outlined as well, the six-node compression branch's loop function and its body kernel took
4.4 + 3.7 s; packed and inline, 7.6 s for the one function (2026-12-01, shared 2-core machine).

A step sequence's inputs are the names it uses and does not define; its outputs are the names a
caller needs afterwards. Names are assigned once per scope (checked by :mod:`.lower`), so "used
and not defined inside" is exactly "defined outside".
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import sympy as sp

from .ir import (
    Arg,
    Call,
    Directions,
    Field,
    Group,
    Iterate,
    Kernel,
    Load,
    Lookup,
    Nodes,
    Reduce,
    Stage,
    Store,
    Switch,
    sym,
)


def _symbols(expr) -> set[str]:
    return {s.name for s in sp.sympify(expr).free_symbols}


def defined(steps) -> set[str]:
    """Every name the steps assign at any depth (loop bodies and branches included)."""
    out: set[str] = set()
    for step in steps:
        if isinstance(step, Stage):
            out |= {s.name for s, _ in step.assignments}
        elif isinstance(step, Call):
            out |= set(step.bind.values())
        elif isinstance(step, Iterate):
            out |= {s.name for s, _ in step.state} | {c[0].name for c in step.carry} | {step.count.name}
            out |= {a[0] for a in step.arrays + step.array_carry}
            out |= defined(step.evaluate) | defined(step.body)
        elif isinstance(step, Switch):
            for _, branch in step.cases:
                out |= defined(branch)
        elif isinstance(step, Load):
            out |= {s.name for s in step.names}
        elif isinstance(step, Directions):
            out |= {s.name for s, _ in step.reads} | defined(step.steps)
        elif isinstance(step, Lookup):
            out |= {name for name, _ in step.tables}
        elif isinstance(step, Nodes):
            out |= {a for _, a in step.writes} | _node_locals(step)
        elif isinstance(step, Reduce):
            out.add(step.name.name)
    return out


def _node_locals(step: Nodes) -> set[str]:
    """The names a node loop binds inside (its reads, sums and stages)."""
    return {s.name for s, _ in step.reads} | {s.name for s, _, _ in step.sums} | defined(step.steps)


def used(steps) -> set[str]:
    """Every name the steps' expressions read at any depth."""
    out: set[str] = set()
    for step in steps:
        if isinstance(step, Stage):
            for _, e in step.assignments:
                out |= _symbols(e)
            for g in step.guards:
                out |= _symbols(g.condition)
        elif isinstance(step, Call):
            for e in step.args.values():
                out |= _symbols(e)
        elif isinstance(step, Iterate):
            exprs = [e for _, e in step.state] + list(step.update) + list(step.scales)
            exprs += [c[1] for c in step.carry] + [c[2] for c in step.carry] + [step.max_iter, step.tol]
            exprs += [a[3] for a in step.arrays] + [step.nodes]
            for e in exprs:
                out |= _symbols(e)
            out |= {a[1] for a in step.arrays + step.array_carry}
            out |= {a[2] for a in step.arrays + step.array_carry}
            out |= used(step.evaluate) | used(step.body)
        elif isinstance(step, Switch):
            out.add(step.selector.name)
            for _, branch in step.cases:
                out |= used(branch)
        elif isinstance(step, Store):
            for e in step.values:
                out |= _symbols(e)
        elif isinstance(step, Directions):
            inner = used(step.steps).union(*(_symbols(e) for e, _ in step.writes))
            out |= inner - {s.name for s, _ in step.reads} - defined(step.steps)
        elif isinstance(step, Lookup):
            out |= _symbols(step.selector)
        elif isinstance(step, Nodes):
            inner = used(step.steps).union(*(_symbols(e) for e, _ in step.writes))
            out |= (inner - _node_locals(step)) | _symbols(step.count)
            out |= {a for _, a in step.reads} | {m for _, m, _ in step.sums} | {a for _, _, a in step.sums}
        elif isinstance(step, Reduce):
            out |= {step.array} | ({step.weights} if step.weights else set()) | _symbols(step.count)
    return out


def visible(steps) -> list[str]:
    """The names the steps leave defined for what follows, in definition order (a switch: the names
    every branch defines)."""
    out: list[str] = []
    for step in steps:
        if isinstance(step, Stage):
            out += [s.name for s, _ in step.assignments]
        elif isinstance(step, Call):
            out += list(step.bind.values())
        elif isinstance(step, Iterate):
            out += [s.name for s, _ in step.state] + [c[0].name for c in step.carry] + [step.count.name]
            out += [a[0] for a in step.arrays + step.array_carry]
            out += visible(step.evaluate)
        elif isinstance(step, Switch):
            branches = [visible(b) for _, b in step.cases]
            common = set.intersection(*(set(b) for b in branches)) if branches else set()
            out += [n for n in branches[0] if n in common] if branches else []
        elif isinstance(step, Load):
            out += [s.name for s in step.names]
        elif isinstance(step, Lookup):
            out += [name for name, _ in step.tables]
        elif isinstance(step, Nodes):
            out += [a for _, a in step.writes]
        elif isinstance(step, Reduce):
            out.append(step.name.name)
    return out


def prune(steps, live: set[str]) -> tuple:
    """The steps without the assignments and bindings nothing uses: ``live`` holds the names used
    after them (a derivative kernel's outputs). A call that can fail stays, and so does every guard;
    a name every branch of a switch defines is kept in all of them or in none."""
    out: list = []
    live = set(live)
    for step in reversed(tuple(steps)):
        if isinstance(step, Stage):
            keep = []
            for s, e in reversed(step.assignments):
                if s.name in live:
                    keep.append((s, e))
                    live |= _symbols(e)
            for g in step.guards:
                live |= _symbols(g.condition)
            if keep or step.guards:
                names = {s.name for s, _ in keep}
                opaque = tuple(n for n in step.opaque if n in names)
                out.append(replace(step, assignments=tuple(reversed(keep)), opaque=opaque))
        elif isinstance(step, Call):
            bind = {o: n for o, n in step.bind.items() if n in live}
            if bind or step.kernel.status:
                out.append(replace(step, bind=bind))
                for e in step.args.values():
                    live |= _symbols(e)
        elif isinstance(step, Iterate):
            inner = {s.name for s, _ in step.state} | {c[0].name for c in step.carry}
            inner |= {a[0] for a in step.arrays + step.array_carry}
            exprs = list(step.update) + [c[2] for c in step.carry] + list(step.scales)
            exprs += [a[3] for a in step.arrays] + [step.nodes]
            need = set(live) | inner | set().union(*map(_symbols, exprs + [step.tol, step.max_iter]))
            need |= {a[2] for a in step.arrays + step.array_carry}
            while True:  # the body reads what the evaluation defines, the evaluation the state
                body = prune(step.body, need)
                evaluate = prune(step.evaluate, need | used(body))
                grown = need | used(body) | used(evaluate)
                if grown == need:
                    break
                need = grown
            step = replace(step, evaluate=evaluate, body=body)
            out.append(step)
            live = (live - defined((step,))) | used((step,))
        elif isinstance(step, Load):
            if any(s.name in live for s in step.names):
                out.append(step)
        elif isinstance(step, Nodes):
            writes = tuple((e, a) for e, a in step.writes if a in live)
            # a loop whose values nothing uses stays for its checks (a guard fails the kernel)
            if writes or any(isinstance(st, Stage) and st.guards for st in step.steps):
                inner = set().union(*(_symbols(e) for e, _ in writes))
                body = prune(step.steps, inner)
                need = used(body) | inner
                step = replace(
                    step,
                    writes=writes,
                    steps=body,
                    reads=tuple((n, a) for n, a in step.reads if n.name in need),
                    sums=tuple((n, m, a) for n, m, a in step.sums if n.name in need),
                )
                out.append(step)
                live = (live - {a for _, a in writes}) | used((step,))
        elif isinstance(step, Reduce):
            if step.name.name in live:
                out.append(step)
                live = (live - {step.name.name}) | used((step,))
        elif isinstance(step, Lookup):
            tables = tuple((n, t) for n, t in step.tables if n in live)
            if tables:
                out.append(replace(step, tables=tables))
                live |= _symbols(step.selector)
        elif isinstance(step, Directions):
            inner = set().union(*(_symbols(e) for e, _ in step.writes))
            step = replace(step, steps=prune(step.steps, inner))
            out.append(step)
            live |= used((step,))
        elif isinstance(step, Store):
            out.append(step)
            live |= used((step,))
        elif isinstance(step, Switch):
            want = set(live)
            while True:
                cases = [(v, prune(b, want)) for v, b in step.cases]
                publics = [{n for n in defined(b) if not n.startswith("_")} for _, b in cases]
                both = set.union(*publics) - set.intersection(*publics)
                if not both - want:
                    break
                want |= both
            step = Switch(step.selector, tuple(cases), step.comment)
            out.append(step)
            live = (live - defined((step,))) | used((step,))
        else:
            out.append(step)
    return tuple(reversed(out))


def prune_rows(steps) -> tuple:
    """The steps without the rows of the direction array nothing reads: a :class:`~.ir.Directions`
    block reads only the rows its code uses, and a store or write to a row no block reads and no
    load loads is dropped (repeated until nothing changes)."""
    steps = tuple(steps)
    while True:
        steps = _trim_reads(steps)
        read = _rows_read(steps)
        trimmed = _trim_writes(steps, read)
        if trimmed == steps:
            return steps
        steps = trimmed


def _walk(steps, fn):
    out = []
    for step in steps:
        if isinstance(step, Iterate):
            step = replace(step, evaluate=_walk(step.evaluate, fn), body=_walk(step.body, fn))
        elif isinstance(step, Switch):
            step = Switch(step.selector, tuple((v, _walk(b, fn)) for v, b in step.cases), step.comment)
        step = fn(step)
        if step is not None:
            out.append(step)
    return tuple(out)


def _trim_reads(steps) -> tuple:
    def fn(step):
        if isinstance(step, Directions):
            inner = used(step.steps).union(*(_symbols(e) for e, _ in step.writes))
            return replace(step, reads=tuple((s, r) for s, r in step.reads if s.name in inner))
        return step

    return _walk(steps, fn)


def _rows_read(steps) -> set[int]:
    rows: set[int] = set()

    def fn(step):
        if isinstance(step, Directions):
            rows.update(r for _, r in step.reads)
        elif isinstance(step, Load):
            rows.add(step.row)
        return step

    _walk(steps, fn)
    return rows


def _trim_writes(steps, read: set[int]) -> tuple:
    def fn(step):
        if isinstance(step, Store):
            return step if step.row in read else None
        if isinstance(step, Directions):
            writes = tuple((e, r) for e, r in step.writes if r in read)
            if not writes:
                return None
            return replace(
                step, writes=writes, steps=prune(step.steps, set().union(*(_symbols(e) for e, _ in writes)))
            )
        return step

    return _walk(steps, fn)


def _has_loop(steps) -> bool:
    for step in steps:
        if isinstance(step, Iterate):
            return True
        if isinstance(step, Switch) and any(_has_loop(b) for _, b in step.cases):
            return True
    return False


@dataclass
class Outliner:
    """Outlines the switch branches of one kernel's steps that hold a loop into kernels named
    ``<base>_<n>``, collected by ``emit`` (the caller places them in a module)."""

    base: str
    module: str
    emit: Callable[[Kernel], None]
    count: int = 0

    def _kernel(self, steps: tuple, inputs: list[str], outputs: list[str], what: str) -> Kernel:
        name = f"{self.base}_{self.count}"
        self.count += 1
        return Kernel(
            name=name,
            summary=f"{what[0].upper()}{what[1:]} of {self.base} (outlined: derive/outline.py).",
            equations=(),
            args=tuple(Arg(sym(n), "value of the caller's variable") for n in inputs),
            steps=steps,
            outputs=Group("", tuple(Field(n, "result for the caller") for n in outputs)),
            module=self.module,
            check_inputs=False,
            check_outputs=False,
            doc_args="the caller's variables of the same names.",
            doc_returns=(("the names every branch defines", "in the order the caller binds them"),),
        )

    def _call(self, steps: tuple, outputs: list[str], what: str) -> Call:
        inputs = sorted(used(steps) - defined(steps))
        kernel = self._kernel(steps, inputs, outputs, what)
        self.emit(kernel)
        return Call(kernel, {n: sym(n) for n in inputs}, {n: n for n in outputs}, comment=what)

    def steps(self, steps, needed: set[str]) -> tuple:
        """The steps with every switch whose branches hold a loop outlined (at any depth);
        ``needed``: the names used after the steps."""
        out = []
        steps = tuple(steps)
        for i, step in enumerate(steps):
            after = used(steps[i + 1 :]) | set(needed)
            if isinstance(step, Switch) and any(_has_loop(b) for _, b in step.cases):
                out.append(self.switch(step, after))
            elif isinstance(step, Iterate):
                inner = after | used((step,))
                evaluate, body = self.steps(step.evaluate, inner), self.steps(step.body, inner)
                out.append(replace(step, evaluate=evaluate, body=body))
            else:
                out.append(step)
        return tuple(out)

    def switch(self, sw: Switch, after: set[str]) -> Switch:
        """Each branch becomes a kernel returning the names all branches define that are used
        ``after`` the switch."""
        common = set.intersection(*(set(visible(b)) for _, b in sw.cases))
        exported = [n for n in visible(sw.cases[0][1]) if n in common and n in after]
        cases = tuple(
            (
                value,
                (
                    self._call(
                        self.steps(steps, set(exported)), exported, f"branch {sw.selector.name} = {value}"
                    ),
                ),
            )
            for value, steps in sw.cases
        )
        return Switch(sw.selector, cases, sw.comment)


__all__ = ["Outliner", "defined", "prune", "prune_rows", "used", "visible"]
