"""Forward-mode differentiation of the kernel IR: JVP and Jacobian kernels of any :class:`~.ir.Kernel`.

:meth:`Differentiator.jvp` turns a kernel into one that also takes a direction (``<arg>__tan`` for
each differentiated argument) and returns, besides its outputs, the derivative of every output
along it (``<output>__tan``). :meth:`Differentiator.jacobian` calls that JVP kernel once per
argument of ``wrt`` with a unit direction and returns every output's derivative with respect to
each, named ``d_<output>__<argument>``. Symbolic forward mode over the declaration, step by step:

- :class:`~.ir.Stage`: each assignment ``y = f(x, ...)`` is followed by its tangent,
  ``y__tan = sum_x df/dx * x__tan`` (SymPy ``diff``), so one CSE per stage shares the
  subexpressions of a value and its derivative. A name whose tangent is identically zero gets no
  tangent variable. Guards are unchanged (a derivative is taken where the value exists).
- :class:`~.ir.Call`: the callee's own JVP kernel (generated once per callee and set of arguments
  that carry a tangent) gets the arguments' tangents: the chain rule, done by the callee.
- :class:`~.ir.Iterate`: the tangents of the state variables are carried through every pass
  (:attr:`~.ir.Iterate.carry`, outside the convergence test): the derivative of the iterate the
  loop stops at, which is what the map returns (derivatives through the iterations). What the
  loop evaluates at every iterate (:attr:`~.ir.Iterate.evaluate`) keeps its tangents after it.
- :class:`~.ir.Switch`: each branch is differentiated; a tangent one branch defines is zero in the
  others.

The loops and branches of a derivative kernel are then outlined into kernels of their own
(:mod:`.outline`), which keeps numba's compile time near linear in the code size.

Almost-everywhere derivatives: ``sign``, ``floor`` and ``ceiling`` differentiate to 0 (SymPy's
``DiracDelta`` / unevaluated ``Derivative``); ``Abs`` to ``sign``; ``Max``/``Min`` to a Heaviside
step. At such a kink the derivative is one-sided or the mean of both sides, as printed.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .ir import Arg, Call, Field, Group, Iterate, Kernel, Stage, Switch, sym
from .outline import Outliner, visible

#: A tangent per direction: direction name -> expression (0 when the value does not depend on it).
_Tangent = dict[str, sp.Basic]


def tangent_name(name: str, wrt: str | None = None) -> str:
    """The variable holding d name / d wrt, ``d_<name>__<wrt>`` (``_d_x__w`` for a branch-local
    ``_x``), or the tangent ``<name>__tan`` along a JVP's direction (``wrt`` None). The double
    underscore keeps them apart from the declarations' names (which use ``d_`` for decompression)."""
    if wrt is None:
        return f"{name}__tan"
    return f"_d{name}__{wrt}" if name.startswith("_") else f"d_{name}__{wrt}"


def derivative_fields(outputs: Group, wrt: tuple[str | None, ...]) -> tuple[Field, ...]:
    """Every output's derivative with respect to every ``wrt`` (None: along a JVP's direction)."""
    return tuple(
        Field(
            tangent_name(f.name, w),
            f"d {f.name} / d {w}" if w else f"derivative of {f.name} along the direction",
        )
        for f in outputs.fields()
        for w in wrt
    )


def _clean(expr: sp.Basic) -> sp.Basic:
    """Almost-everywhere derivatives: DiracDelta (from sign) and d floor, d ceiling are 0 (also of a
    compound argument, where SymPy writes ``Subs(Derivative(floor(xi), xi), xi, arg)``). Anything
    SymPy leaves unevaluated is refused: it would print as code that fails only when compiled."""
    expr = expr.replace(lambda e: isinstance(e, sp.DiracDelta), lambda e: sp.S.Zero)
    expr = expr.replace(
        lambda e: isinstance(e, sp.Derivative) and isinstance(e.expr, (sp.floor, sp.ceiling)),
        lambda e: sp.S.Zero,
    )
    expr = expr.replace(lambda e: isinstance(e, sp.Subs) and e.expr == 0, lambda e: sp.S.Zero)
    left = [e for e in sp.preorder_traversal(expr) if isinstance(e, (sp.Derivative, sp.Subs))]
    if left:
        raise ValueError(f"no derivative of {left[0]} (not differentiable in closed form)")
    return expr


@dataclass
class _Frame:
    """The tangents known at one point of a kernel body, by variable name."""

    wrt: tuple[str, ...]
    tangents: dict[str, _Tangent]

    def of(self, expr: sp.Basic) -> _Tangent:
        """The tangent of ``expr`` in every direction (chain rule over its free symbols)."""
        expr = sp.sympify(expr)
        out = {w: sp.S.Zero for w in self.wrt}
        for s in sorted(expr.free_symbols, key=lambda s: s.name):
            t = self.tangents.get(s.name)
            if t is None or all(v == 0 for v in t.values()):
                continue
            d = _clean(sp.diff(expr, s))
            if d == 0:
                continue
            for w in self.wrt:
                if t[w] != 0:
                    out[w] += d * t[w]
        return out

    def bind(self, name: str, tangent: _Tangent) -> list[tuple[sp.Symbol, sp.Basic]]:
        """Record ``name``'s tangent; the assignments of its nonzero directions."""
        assigns, rec = [], {}
        for w in self.wrt:
            if tangent[w] == 0:
                rec[w] = sp.S.Zero
            else:
                s = sym(tangent_name(name, w))
                assigns.append((s, tangent[w]))
                rec[w] = s
        self.tangents[name] = rec
        return assigns

    def copy(self) -> _Frame:
        return _Frame(self.wrt, {k: dict(v) for k, v in self.tangents.items()})


@dataclass
class Differentiator:
    """Builds derivative kernels, each once, kept in :attr:`kernels` (name -> kernel) for the
    generator to place in ``<primal module>_jacobian``.

    - :meth:`jvp`: the kernel plus one directional derivative (a Jacobian-vector product): extra
      arguments ``<arg>__tan`` (the direction, for the ``active`` arguments), extra outputs
      ``<out>__tan``. Its outputs are not checked for finiteness (its callers check theirs): an
      infinite derivative of an output the caller does not use must not fail the caller.
    - :meth:`jacobian`: all outputs and their derivatives with respect to ``wrt``, one call of the
      JVP kernel per direction (unit seeds). One direction per call keeps each generated function
      about twice the size of the primal one (numba's compile time grows faster than linearly with
      a function's size), at the cost of recomputing the values once per direction.
    """

    kernels: dict[str, Kernel] = field(default_factory=dict)
    _memo: dict[tuple, Kernel] = field(default_factory=dict)

    def jvp(self, kernel: Kernel, active: tuple[str, ...]) -> Kernel:
        """``kernel`` and the derivative of every output along a direction in its ``active``
        arguments, given as the extra arguments ``<arg>__tan``."""
        unknown = [a for a in active if a not in kernel.arg_names]
        if unknown:
            raise ValueError(f"kernel {kernel.name}: cannot differentiate with respect to {unknown}")
        key = ("jvp", kernel.module, kernel.name, tuple(active))
        if key in self._memo:
            return self._memo[key]
        frame = _Frame((None,), {})
        for a in kernel.args:
            frame.tangents[a.name] = {None: sym(tangent_name(a.name)) if a.name in active else sp.S.Zero}
        ctx = _Ctx(self, frame)
        steps = ctx.steps(kernel.steps)
        fields = derivative_fields(kernel.outputs, (None,))
        # a derivative output that is identically zero still needs its variable
        zeros = [
            (sym(tangent_name(f.name)), sp.S.Zero)
            for f in kernel.outputs.fields()
            if ctx.frame.tangents.get(f.name, {}).get(None, sp.S.Zero) == 0
        ]
        if zeros:
            steps += (Stage(tuple(zeros), comment="derivatives that are identically zero"),)
        name = f"{kernel.name}_jvp" + ("" if active == kernel.arg_names else "_" + "_".join(active))
        module = f"{kernel.module}_jacobian"
        steps = Outliner(name, module, self._add).steps(
            steps, list(kernel.outputs.names()) + [f.name for f in fields]
        )
        out = Kernel(
            name=name,
            summary=f"{kernel.summary.rstrip('.')}, with the derivative of every output along the "
            f"direction ({', '.join(tangent_name(a) for a in active)}).",
            equations=kernel.equations,
            args=kernel.args
            + tuple(Arg(sym(tangent_name(a)), f"direction: its component along {a}") for a in active),
            steps=steps,
            outputs=Group("", kernel.outputs.items + fields),
            status=kernel.status,
            notes="Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); "
            "through an iteration, of the iterate it stops at.",
            module=module,
            check_inputs=kernel.check_inputs,
            check_outputs=False,
        )
        self._memo[key] = out
        self._add(out)
        return out

    def jacobian(
        self,
        kernel: Kernel,
        wrt: tuple[str, ...],
        *,
        name: str,
        summary: str,
        batch=None,
    ) -> Kernel:
        """``kernel``'s outputs and their derivatives ``d_<out>__<w>`` with respect to each ``w`` of
        ``wrt``: one call of :meth:`jvp` per direction."""
        jvp = self.jvp(kernel, tuple(wrt))
        outs = kernel.outputs.names()
        steps = []
        for w in wrt:
            seeds = {tangent_name(a): sp.S.One if a == w else sp.S.Zero for a in wrt}
            bind = {tangent_name(o): tangent_name(o, w) for o in outs}
            if w == wrt[0]:
                bind.update({o: o for o in outs})
            args = {**{a.name: a.symbol for a in kernel.args}, **seeds}
            steps.append(Call(jvp, args, bind, comment=f"derivatives with respect to {w}"))
        out = Kernel(
            name=name,
            summary=summary,
            equations=kernel.equations,
            args=kernel.args,
            steps=tuple(steps),
            outputs=Group("", kernel.outputs.items + derivative_fields(kernel.outputs, tuple(wrt))),
            status=kernel.status,
            batch=batch,
            notes=jvp.notes,
            module=f"{kernel.module}_jacobian",
            check_inputs=kernel.check_inputs,
            check_outputs=kernel.check_outputs,
        )
        self._add(out)
        return out

    def _add(self, kernel: Kernel) -> None:
        if kernel.name in self.kernels:
            raise ValueError(f"two generated kernels named {kernel.name}")
        self.kernels[kernel.name] = kernel


@dataclass
class _Ctx:
    diff: Differentiator
    frame: _Frame

    def steps(self, steps) -> tuple:
        out: list = []
        for step in steps:
            if isinstance(step, Stage):
                out.append(self.stage(step))
            elif isinstance(step, Call):
                out.extend(self.call(step))
            elif isinstance(step, Iterate):
                out.append(self.iterate(step))
            elif isinstance(step, Switch):
                out.append(self.switch(step))
            else:
                raise TypeError(f"cannot differentiate a {type(step).__name__}")
        return tuple(out)

    def stage(self, st: Stage) -> Stage:
        assigns: list[tuple[sp.Symbol, sp.Basic]] = []
        for s, expr in st.assignments:
            assigns.append((s, expr))
            assigns.extend(self.frame.bind(s.name, self.frame.of(expr)))
        return Stage(tuple(assigns), st.guards, st.comment)

    def call(self, c: Call) -> list:
        """The callee's JVP kernel along the arguments' tangents (the chain rule, by the callee)."""
        callee = c.kernel
        arg_t = {a: self.frame.of(c.args[a]) for a in callee.arg_names}
        active = tuple(a for a in callee.arg_names if any(v != 0 for v in arg_t[a].values()))
        if not active or not c.bind:
            for local in c.bind.values():
                self.frame.bind(local, {w: sp.S.Zero for w in self.frame.wrt})
            return [c]
        (w,) = self.frame.wrt
        jvp = self.diff.jvp(callee, active)
        args = {**c.args, **{tangent_name(a): arg_t[a][w] for a in active}}
        bind = dict(c.bind)
        for out, local in c.bind.items():
            bind[tangent_name(out)] = tangent_name(local, w)
            self.frame.tangents[local] = {w: sym(tangent_name(local, w))}
        return [Call(jvp, args, bind, comment=c.comment)]

    def iterate(self, it: Iterate) -> Iterate:
        outer = self.frame.copy()
        wrt = self.frame.wrt
        # every state variable carries a tangent (its update may depend on active inputs)
        carry: list[tuple[sp.Symbol, sp.Basic, sp.Basic]] = []
        inits = {s.name: outer.of(init) for s, init in it.state}
        for s, _ in it.state:
            self.frame.tangents[s.name] = {w: sym(tangent_name(s.name, w)) for w in wrt}
        for s, init in it.carry:
            inits[s.name] = outer.of(init)
            self.frame.tangents[s.name] = {w: sym(tangent_name(s.name, w)) for w in wrt}
        self.frame.tangents[it.count.name] = {w: sp.S.Zero for w in wrt}
        evaluate = self.steps(it.evaluate)
        evaluated = {n: dict(self.frame.tangents[n]) for n in visible(it.evaluate)}
        body = self.steps(it.body)
        updates = [self.frame.of(u) for u in it.update] + [self.frame.of(u) for _, _, u in it.carry]
        names = [s for s, _ in it.state] + [s for s, _, _ in it.carry]
        for s, t in zip(names, updates, strict=True):
            for w in wrt:
                carry.append((sym(tangent_name(s.name, w)), inits[s.name][w], t[w]))
        # after the loop only the state variables, the carried ones and the count are visible
        self.frame = outer
        for s in names:
            self.frame.tangents[s.name] = {w: sym(tangent_name(s.name, w)) for w in wrt}
        self.frame.tangents[it.count.name] = {w: sp.S.Zero for w in wrt}
        # what the loop evaluates at every iterate keeps its tangents after it
        self.frame.tangents.update(evaluated)
        return Iterate(
            state=it.state,
            body=body,
            update=it.update,
            max_iter=it.max_iter,
            tol=it.tol,
            scales=it.scales,
            count=it.count,
            fail_status=it.fail_status,
            comment=it.comment,
            carry=tuple(it.carry) + tuple(carry),
            evaluate=evaluate,
        )

    def switch(self, sw: Switch) -> Switch:
        before = self.frame.copy()
        branches = []
        for value, steps in sw.cases:
            self.frame = before.copy()
            new = self.steps(steps)
            branches.append((value, new, self.frame))
        defined = [set(f.tangents) - set(before.tangents) for _, _, f in branches]
        common = set.intersection(*defined) if defined else set()
        wrt = before.wrt
        merged = before.copy()
        cases = []
        for value, new, f in branches:
            fill = []
            for name in sorted(common):
                for w in wrt:
                    if f.tangents[name][w] == 0 and any(g.tangents[name][w] != 0 for _, _, g in branches):
                        fill.append((sym(tangent_name(name, w)), sp.S.Zero))
            if fill:
                new = new + (Stage(tuple(fill), comment="tangents the other branches define"),)
            cases.append((value, new))
        for name in sorted(common):
            merged.tangents[name] = {
                w: sym(tangent_name(name, w))
                if any(g.tangents[name][w] != 0 for _, _, g in branches)
                else sp.S.Zero
                for w in wrt
            }
        self.frame = merged
        return Switch(sw.selector, tuple(cases), sw.comment)


__all__ = ["Differentiator", "derivative_fields", "tangent_name"]
