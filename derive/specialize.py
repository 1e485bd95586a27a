"""Specialization: a kernel for one choice of its specialized options, the option not an argument.

An :class:`~.declaration.Option` declared ``specialize=True`` selects different callees by its
choice (the iterative maps' ``zeroth``: another map's stance as the zeroth iterate; ``nodes``: the
node count's half kernels). numba compiles every callee a kernel can reach, in every branch, so a
kernel that switched on such an option at run time compiled all of its choices' callees on its
first call. A declaration instead builds its kernels with the option as an argument (the generic
form, never emitted), and :func:`specialize` gives the kernel of one choice:

- the option's symbol is replaced by the choice's code everywhere (assignments, guards, calls,
  loops), so a :class:`~.ir.Switch` on it keeps the one branch (inlined in place) and a
  ``Piecewise`` on it folds;
- a guard that folds to true is dropped (the option's own checks); one that folds to false is an
  error of the declaration;
- a callee given the code for an argument of the option's name is specialized the same way
  (``<callee>_<option>_<choice>``, in the callee's module), so the choice reaches every kernel
  below;
- the option is not an argument: the runtime picks the kernel of the choice by name from the
  index (``Kernel.signature``'s ``choices``).

Derivatives (:mod:`.tangent`) differentiate the specialized kernels: their Jacobians follow.
Specialized kernels are cached, so every caller of one shares the same kernel object.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import sympy as sp

from .ir import Call, Guard, Iterate, Kernel, Lookup, Nodes, Reduce, Stage, Switch, calls, sym

__all__ = ["choice_of", "choice_suffix", "module_kernels", "specialize"]

_CACHE: dict[tuple, Kernel] = {}
#: id of every specialized kernel (kept alive by the cache) -> the suffix of its choice
_SUFFIXES: dict[int, str] = {}


def _ident(value: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in value)


def choice_suffix(choice: Mapping[str, tuple[int, str]]) -> str:
    """The name suffix of a choice (option name -> (code, value)): ``_zeroth_geyer_nodes_4``."""
    return "".join(f"_{name}_{_ident(value)}" for name, (_, value) in choice.items())


def _expr(x, subs):
    return sp.sympify(x).xreplace(subs) if subs else x


def _guards(guards, subs, where):
    out = []
    for g in guards:
        cond = _expr(g.condition, subs)
        if cond is sp.true:
            continue
        if cond is sp.false:
            raise ValueError(f"{where}: guard {g.doc or g.status} always fails for this choice")
        out.append(Guard(cond, g.status, g.doc))
    return tuple(out)


def _steps(steps, subs, choice, labels, where) -> tuple:
    out: list = []
    for step in steps:
        if isinstance(step, Stage):
            out.append(
                replace(
                    step,
                    assignments=tuple((s, _expr(e, subs)) for s, e in step.assignments),
                    guards=_guards(step.guards, subs, where),
                )
            )
        elif isinstance(step, Call):
            args = {k: _expr(v, subs) for k, v in step.args.items()}
            taken = {}
            for name, value in args.items():
                if name in labels and isinstance(value, sp.Number):
                    code = int(value)
                    taken[name] = (code, labels[name][code])
            kernel = step.kernel
            if taken and not kernel.external:
                kernel = specialize(kernel, taken, labels)
                args = {k: v for k, v in args.items() if k not in taken}
            out.append(replace(step, kernel=kernel, args=args))
        elif isinstance(step, Iterate):
            out.append(
                replace(
                    step,
                    state=tuple((s, _expr(e, subs)) for s, e in step.state),
                    body=_steps(step.body, subs, choice, labels, where),
                    evaluate=_steps(step.evaluate, subs, choice, labels, where),
                    update=tuple(_expr(e, subs) for e in step.update),
                    max_iter=_expr(step.max_iter, subs),
                    tol=_expr(step.tol, subs),
                    scales=tuple(_expr(e, subs) for e in step.scales),
                    carry=tuple((s, _expr(a, subs), _expr(b, subs)) for s, a, b in step.carry),
                    arrays=tuple((a, i, u, _expr(c, subs)) for a, i, u, c in step.arrays),
                    nodes=_expr(step.nodes, subs),
                )
            )
        elif isinstance(step, Nodes):
            out.append(
                replace(
                    step,
                    count=_expr(step.count, subs),
                    steps=_steps(step.steps, subs, choice, labels, where),
                    writes=tuple((_expr(e, subs), a) for e, a in step.writes),
                )
            )
        elif isinstance(step, Reduce):
            out.append(replace(step, count=_expr(step.count, subs)))
        elif isinstance(step, Lookup):
            out.append(replace(step, selector=_expr(step.selector, subs)))
        elif isinstance(step, Switch):
            if step.selector.name in choice:
                code = choice[step.selector.name][0]
                branch = dict(step.cases).get(code)
                if branch is None:
                    raise ValueError(f"{where}: switch on {step.selector.name} has no case {code}")
                out.extend(_steps(branch, subs, choice, labels, where))
            else:
                cases = tuple((c, _steps(b, subs, choice, labels, where)) for c, b in step.cases)
                out.append(replace(step, cases=cases))
        else:
            raise TypeError(f"{where}: cannot specialize a {type(step).__name__}")
    return tuple(out)


def specialize(
    kernel: Kernel,
    choice: Mapping[str, tuple[int, str]],
    labels: Mapping[str, tuple[str, ...]],
    name: str | None = None,
) -> Kernel:
    """``kernel`` for ``choice`` (option name -> (code, value)) without those arguments, named
    ``name`` (default ``<kernel>`` + :func:`choice_suffix`). ``labels`` gives each specialized
    option's values by code (to name the callees it reaches)."""
    choice = {n: choice[n] for n in kernel.arg_names if n in choice}
    name = name or kernel.name + choice_suffix(choice)
    key = (kernel.module, kernel.name, name, tuple(choice.items()))
    if key not in _CACHE:
        subs = {sym(n): sp.Integer(code) for n, (code, _) in choice.items()}
        where = f"kernel {name}"
        layout = kernel.layout
        if layout is not None:
            layout = replace(layout, p=tuple(n for n in layout.p if n not in choice))
        _CACHE[key] = replace(
            kernel,
            name=name,
            args=tuple(a for a in kernel.args if a.name not in choice),
            steps=_steps(kernel.steps, subs, choice, labels, where),
            layout=layout,
        )
        _SUFFIXES[id(_CACHE[key])] = choice_suffix(choice)
    return _CACHE[key]


def choice_of(kernel: Kernel) -> str:
    """The choice suffix (:func:`choice_suffix`) of a kernel :func:`specialize` made, else ""."""
    return _SUFFIXES.get(id(kernel), "")


def _reached(kernels, module: str) -> list[Kernel]:
    """The kernels of ``module`` that ``kernels`` call, at any depth, callees first."""
    seen: dict[str, Kernel] = {}

    def walk(steps) -> None:
        for c in calls(steps):
            k = c.kernel
            if k.module == module and k.name not in seen:
                walk(k.steps)
                seen.setdefault(k.name, k)

    for k in kernels:
        walk(k.steps)
    return list(seen.values())


def module_kernels(module: str, helpers, main, labels: Mapping[str, tuple[str, ...]]) -> tuple[Kernel, ...]:
    """A declaration's module: the ``helpers`` that take no specialized option (other modules may
    call them), the kernels of ``module`` that ``main`` calls (the specialized helpers among them),
    then ``main``."""
    names = {k.name for k in main}
    out = {h.name: h for h in helpers if not any(a in labels for a in h.arg_names)}
    for k in _reached(main, module):
        if k.name not in names:
            out.setdefault(k.name, k)
    return tuple(out.values()) + tuple(main)
