"""Kernel specifications and their lowering to template data.

A :class:`Kernel` is a scalar function of named arguments computed in :class:`Stage` s: each
stage assigns named quantities (one common-subexpression elimination over the whole stage, so
temporaries are shared between its outputs, as PyDy does) and may then check guards. A guard
is a condition that must hold for the later stages to be defined (a real square root, an
arcsine argument in [-1, 1], ...); when it fails (or is NaN) the kernel returns NaN outputs and
the guard's status code. Kernels never raise.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .printer import to_code
from .status import STATUS_CODES

_STATUS = {name: code for name, code, _ in STATUS_CODES}


@dataclass(frozen=True)
class Arg:
    symbol: sp.Symbol
    doc: str


@dataclass(frozen=True)
class Guard:
    condition: sp.Basic  # must hold; NaN counts as failure
    status: str
    doc: str = ""

    def __post_init__(self):
        if self.status not in _STATUS:
            raise ValueError(f"unknown status {self.status!r}")
        if self.condition in (sp.true, sp.false) or isinstance(self.condition, bool):
            # SymPy folded the condition through symbol assumptions (e.g. a positive=True symbol):
            # the run-time check would vanish. Build it from kernel.real(...) symbols instead.
            raise ValueError(f"guard for {self.status} folds to the constant {self.condition}")


@dataclass(frozen=True)
class Stage:
    assignments: tuple[tuple[sp.Symbol, sp.Basic], ...]
    guards: tuple[Guard, ...] = ()
    comment: str = ""


@dataclass(frozen=True)
class Output:
    symbol: sp.Symbol
    doc: str


@dataclass(frozen=True)
class Kernel:
    """One generated scalar function (and, with ``batch=True``, a parallel batch wrapper)."""

    name: str
    summary: str
    equations: tuple[str, ...]
    args: tuple[Arg, ...]
    stages: tuple[Stage, ...]
    outputs: tuple[Output, ...]
    with_status: bool = True
    batch: bool = True
    check_finite_inputs: bool = True
    notes: str = ""
    extra_input_guards: tuple[Guard, ...] = field(default_factory=tuple)


def real(sym: sp.Symbol) -> sp.Symbol:
    """The same-named symbol without sign assumptions, for guards SymPy must not fold to True."""
    return sp.Symbol(sym.name, real=True)


def positive(*syms: sp.Symbol) -> sp.Basic:
    """Guard condition: every symbol is > 0 (checked at run time, whatever its assumptions)."""
    return sp.And(*(real(s) > 0 for s in syms))


def _cse_stage(stage: Stage, counter: list[int]):
    names = [s for s, _ in stage.assignments]
    exprs = []
    # CSE temporaries are emitted before the stage's named assignments, so an assignment that uses
    # an earlier one of the same stage gets it inlined (CSE then shares it again).
    for i, (_, expr) in enumerate(stage.assignments):
        expr = sp.sympify(expr)
        for j in range(i - 1, -1, -1):
            expr = expr.subs(names[j], exprs[j])
        exprs.append(expr)
    start = counter[0]
    temps_gen = sp.numbered_symbols("_x", start=start)
    replacements, reduced = sp.cse(exprs, symbols=temps_gen, order="canonical")
    counter[0] = start + len(replacements)
    ops = sum(sp.count_ops(e) for _, e in replacements) + sum(sp.count_ops(e) for e in reduced)
    temps = [(str(sym), to_code(expr)) for sym, expr in replacements]
    assigns = [(str(n), to_code(e)) for n, e in zip(names, reduced, strict=True)]
    return temps, assigns, int(ops)


def lower(kernel: Kernel) -> dict:
    """Template data for one kernel: signature, docstring lines, statements, returns."""
    counter = [0]
    stages = []
    total_ops = 0
    guards_in = []
    if kernel.check_finite_inputs:
        finite = " and ".join(f"math.isfinite({a.symbol})" for a in kernel.args)
        guards_in.append({"code": finite, "status": _STATUS["INVALID_INPUT"], "name": "INVALID_INPUT"})
    for g in kernel.extra_input_guards:
        guards_in.append({"code": to_code(g.condition), "status": _STATUS[g.status], "name": g.status})
    for stage in kernel.stages:
        temps, assigns, ops = _cse_stage(stage, counter)
        total_ops += ops
        stages.append(
            {
                "comment": stage.comment,
                "temps": temps,
                "assigns": assigns,
                "guards": [
                    {
                        "code": to_code(g.condition),
                        "status": _STATUS[g.status],
                        "name": g.status,
                        "doc": g.doc,
                    }
                    for g in stage.guards
                ],
            }
        )
    if not kernel.with_status and (guards_in or any(s["guards"] for s in stages)):
        raise ValueError(f"kernel {kernel.name} has guards but no status output")
    return {
        "name": kernel.name,
        "summary": kernel.summary,
        "equations": ", ".join(kernel.equations),
        "notes": kernel.notes,
        "args": [{"name": str(a.symbol), "doc": a.doc} for a in kernel.args],
        "outputs": [{"name": str(o.symbol), "doc": o.doc} for o in kernel.outputs],
        "input_guards": guards_in,
        "stages": stages,
        "with_status": kernel.with_status,
        "batch": kernel.batch,
        "n_out": len(kernel.outputs),
        "ops": total_ops,
    }
