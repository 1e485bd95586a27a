"""Outlining: a loop body or a switch branch of a kernel becomes a kernel of its own, called in place.

Why: numba's SSA reconstruction costs about (variables assigned more than once) x (statements of
the function). A loop's state and a branch's results are assigned more than once, so a large
function with loops and branches compiles in time quadratic in its size: the Jacobian kernel of
the compression half of Schwind and Koditschek's iteration (five node-count branches, each a loop
carrying 13 values and their 8 tangents) took 300 s. Outlined, every function is either small or
free of reassigned variables. Used for the Jacobian kernels (:mod:`.tangent`); the maps' own
kernels are left as declared.

A step sequence's inputs are the names it uses and does not define; its outputs are the names a
caller needs afterwards. Names are assigned once per scope (checked by :mod:`.lower`), so "used
and not defined inside" is exactly "defined outside".
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from .ir import Arg, Call, Field, Group, Iterate, Kernel, Stage, Switch, sym


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
            out |= defined(step.evaluate) | defined(step.body)
        elif isinstance(step, Switch):
            for _, branch in step.cases:
                out |= defined(branch)
    return out


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
            for e in exprs:
                out |= _symbols(e)
            out |= used(step.evaluate) | used(step.body)
        elif isinstance(step, Switch):
            out.add(step.selector.name)
            for _, branch in step.cases:
                out |= used(branch)
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
            out += visible(step.evaluate)
        elif isinstance(step, Switch):
            branches = [visible(b) for _, b in step.cases]
            common = set.intersection(*(set(b) for b in branches)) if branches else set()
            out += [n for n in branches[0] if n in common] if branches else []
    return out


@dataclass
class Outliner:
    """Outlines the loop bodies and switch branches of one kernel's steps into kernels named
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
            summary=f"{what} of {self.base} (outlined: derive/outline.py).",
            equations=(),
            args=tuple(Arg(sym(n), "value of the caller's variable") for n in inputs),
            steps=steps,
            outputs=Group("", tuple(Field(n, "result for the caller") for n in outputs)),
            module=self.module,
            check_inputs=False,
            check_outputs=False,
        )

    def _call(self, steps: tuple, outputs: list[str], what: str) -> Call:
        inputs = sorted(used(steps) - defined(steps))
        kernel = self._kernel(steps, inputs, outputs, what)
        self.emit(kernel)
        return Call(kernel, {n: sym(n) for n in inputs}, {n: n for n in outputs}, comment=what)

    def steps(self, steps, needed: list[str]) -> tuple:
        """Outline the loops and branches of ``steps``; after a loop, the remaining steps become a
        kernel of their own too (the continuation), returning the ``needed`` names they define, so
        the function holding a loop holds little else."""
        out = []
        steps = tuple(steps)
        for i, step in enumerate(steps):
            if isinstance(step, Iterate):
                tail = steps[i + 1 :]
                out.append(self.iterate(step, used(tail) | set(needed)))
                if tail:
                    after = set(visible(tail))
                    outputs = [n for n in needed if n in after]
                    out.append(self._call(self.steps(tail, outputs), outputs, "continuation"))
                return tuple(out)
            out.append(self.switch(step, needed) if isinstance(step, Switch) else step)
        return tuple(out)

    def iterate(self, it: Iterate, after: set[str]) -> Iterate:
        """The body and the updates become one kernel returning the next values (``_next_<name>``);
        what the loop evaluates at every iterate another, returning what the body, the updates and
        the steps ``after`` the loop read of it. Without a body, one kernel evaluates the iterate and
        returns the next values too (computed once more than needed, at the final iterate)."""
        names = [s.name for s, _ in it.state] + [c[0].name for c in it.carry]
        updates = list(it.update) + [c[2] for c in it.carry]
        nxt = [f"_next{n}" if n.startswith("_") else f"_next_{n}" for n in names]
        final = Stage(tuple((sym(n), u) for n, u in zip(nxt, updates, strict=True)), comment="next values")
        evaluate: tuple = ()
        if it.evaluate and not it.body:
            outputs = [n for n in visible(it.evaluate) if n in after] + nxt
            call = self._call(self.steps(it.evaluate + (final,), outputs), outputs, "evaluation and update")
            evaluate, body = (call,), ()
        else:
            if it.evaluate:
                wanted = used(it.body) | set().union(*map(_symbols, updates)) | after
                read = [n for n in visible(it.evaluate) if n in wanted]
                evaluate = (self._call(self.steps(it.evaluate, read), read, "evaluation of the iterate"),)
            body = (self._call(self.steps(it.body + (final,), nxt), nxt, "loop body"),)
        k = len(it.state)
        return Iterate(
            state=it.state,
            evaluate=evaluate,
            body=body,
            update=tuple(sym(n) for n in nxt[:k]),
            max_iter=it.max_iter,
            tol=it.tol,
            scales=it.scales,
            count=it.count,
            fail_status=it.fail_status,
            comment=it.comment,
            carry=tuple((c[0], c[1], sym(n)) for c, n in zip(it.carry, nxt[k:], strict=True)),
        )

    def switch(self, sw: Switch, needed: list[str]) -> Switch:
        """Each branch becomes a kernel returning every name all branches define (``needed`` is
        passed on to the branches' own continuations)."""
        common = set.intersection(*(set(visible(b)) for _, b in sw.cases)) if sw.cases else set()
        exported = [n for n in visible(sw.cases[0][1]) if n in common] if sw.cases else []
        cases = tuple(
            (
                value,
                (self._call(self.steps(steps, exported), exported, f"branch {sw.selector.name} = {value}"),),
            )
            for value, steps in sw.cases
        )
        return Switch(sw.selector, cases, sw.comment)


__all__ = ["Outliner", "defined", "used", "visible"]
