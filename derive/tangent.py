"""Forward-mode differentiation of the kernel IR, every direction in one pass: Jacobian and JVP kernels.

:meth:`Differentiator.jacobian` turns a kernel into one that returns its outputs and the derivative
of every output with respect to each argument of ``wrt`` (``d_<output>__<argument>``), all from one
call: every quantity the kernel computes carries its value and one tangent per direction together,
as SymForce's ``with_jacobians`` shares one common-subexpression pass between a function's values
and its derivatives (the sin, cos and square roots once, the partial derivatives once for every
direction). Symbolic forward mode over the declaration, step by step:

- :class:`~.ir.Stage`: each assignment ``y = f(x, ...)`` is followed by its tangents,
  ``d_y__w = sum_x df/dx * d_x__w`` for every direction ``w`` (SymPy ``diff``, once per ``x``), so
  the stage's CSE shares the partial derivatives between the directions and with the value. A
  tangent that is identically zero gets no variable, one that is a constant or another variable
  none either (it is used in place). Guards are unchanged (a derivative is taken where the value
  exists).
- :class:`~.ir.Call`: the chain rule, done by a derivative of the callee, whichever computes fewer
  directions:

  * with respect to the callee's arguments that carry a tangent (its Jacobian, unit directions:
    shared by every caller with those arguments active, the map's public stance Jacobian among
    them), then ``d_out__w = sum_a d_out/d_a * d_a__w`` at the call; a Jacobian already generated
    for a superset of the arguments with at most one direction more is reused;
  * or along the caller's directions (a vector JVP kernel, ``d_<arg>__<j>`` the component of
    direction ``j`` along an argument; a direction that is exactly a unit vector or zero along an
    argument is built in, not passed), when the callee has more active arguments than the caller
    has directions reaching it.

  Both are generated once per callee and set of active arguments (pattern of directions).
- :class:`~.ir.Iterate`: the tangents of the state variables are carried through every pass,
  outside the convergence test: the derivative of the iterate the loop stops at, which is what the
  map returns (derivatives through the iterations). What the loop evaluates at every iterate
  (:attr:`~.ir.Iterate.evaluate`) keeps its tangents after it. Where the loop's steps are stages,
  calls and switches of them, at least :data:`LOOPED_SIZE` assignments a pass (the gravity maps'
  fixed points), each pass computes its values and partial derivatives once and then runs its
  tangent code, written once, per direction (:class:`~.ir.Directions`, on the rows of a direction
  array ``_T[row, direction]`` on the kernel's stack; a switch's tangent code in a switch on the
  same option, whose branch reads the partial derivatives its values' branch named), and so do the
  initial values and the stages and calls right after the loop; otherwise every tangent has a
  variable per direction, carried through the passes (:attr:`~.ir.Iterate.carry`). A direction
  that reaches neither the initial values nor anything the loop reads is zero in it.
- :class:`~.ir.Switch`: each branch is differentiated; a tangent one branch defines is zero in the
  others.

What no output needs is then pruned, and the switch branches that hold a loop are outlined into
kernels of their own (:mod:`.outline`; the loops keep their tangents in one tuple, derive/lower.py),
which keeps numba's compile time near linear in the code size. A derivative kernel per choice of a
specialized option (:mod:`.specialize`) returns the result of a kernel holding its steps after its
choice's own calls (a tail :class:`~.ir.Call`), one per distinct code, shared between the choices
(:meth:`Differentiator._thin`).

Cost: see benchmarks/bench_maps.py (e)-(g). Outside loops the directions are unrolled (every tangent
a line of its own per direction), so that code grows with the number of directions, and numba's
compile time is about proportional to the bytecode it compiles (about 0.4 ms per instruction on
the shared 2-core machine; the per-direction loops' array accesses cost more per instruction, so
they save lines and run time rather than compile time). Measured 2026-12-01, bytecode
instructions of iterative_jacobian.py: one-direction JVP called per direction, same lowering,
33,644; unrolled vector mode 52,627; with the large loops' tangent code per direction 38,409.

Almost-everywhere derivatives: ``sign``, ``floor`` and ``ceiling`` differentiate to 0 (SymPy's
``DiracDelta`` / unevaluated ``Derivative``); ``Abs`` to ``sign``; ``Max``/``Min`` to a Heaviside
step. At such a kink the derivative is one-sided or the mean of both sides, as printed. Anything
SymPy leaves unevaluated is refused at generation.
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, is_dataclass, replace

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
from .outline import Outliner, defined, prune, prune_rows, used, visible
from .specialize import choice_of

#: A tangent per direction: direction name -> expression (0 when the value does not depend on it).
_Tangent = dict


def tangent_name(name: str, wrt: str | None = None) -> str:
    """The variable holding d name / d wrt, ``d_<name>__<wrt>`` (``_d_x__w`` for a branch-local
    ``_x``), or the tangent ``<name>__tan`` along a JVP's direction (``wrt`` None). The double
    underscore keeps them apart from the declarations' names (which use ``d_`` for decompression)."""
    if wrt is None:
        return f"{name}__tan"
    return f"_d{name}__{wrt}" if name.startswith("_") else f"d_{name}__{wrt}"


def _entry_name(name: str, arg: str) -> str:
    """The caller's variable holding the callee's d <output bound to name> / d <arg> (a Jacobian
    entry, before the chain rule): ``_j_<name>__<arg>``."""
    return f"_j{name}__{arg}" if name.startswith("_") else f"_j_{name}__{arg}"


def derivative_fields(outputs: Group, wrt: tuple[str | None, ...]) -> tuple[Field, ...]:
    """Every output's derivative with respect to every ``wrt`` (None: along a JVP's direction),
    output-major (the row-major Jacobian after the values)."""
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


def _direct(t: sp.Basic) -> bool:
    """A tangent used in place, without a variable of its own: a number, a variable or a number
    times a variable."""
    if t.is_Number or isinstance(t, sp.Symbol):
        return True
    return isinstance(t, sp.Mul) and len(t.args) == 2 and t.args[0].is_Number and t.args[1].is_Symbol


@dataclass
class _Frame:
    """The tangents known at one point of a kernel body, by variable name: each a number, a
    variable holding it, or (for an argument) the direction's component passed in."""

    wrt: tuple
    tangents: dict[str, _Tangent]
    #: node arrays (derive/ir.py's Nodes): array -> {direction: the name of its tangent array, or
    #: None where the tangent is zero}
    arrays: dict[str, dict] = field(default_factory=dict)

    def partials(self, expr: sp.Basic) -> list[tuple[sp.Basic, _Tangent]]:
        """(d expr / d x, tangent of x) for every free symbol x of ``expr`` with a tangent."""
        expr = sp.sympify(expr)
        out = []
        for s in sorted(expr.free_symbols, key=lambda s: s.name):
            t = self.tangents.get(s.name)
            if t is None or all(v == 0 for v in t.values()):
                continue
            d = _clean(sp.diff(expr, s))
            if d != 0:
                out.append((d, t))
        return out

    def of(self, expr: sp.Basic) -> _Tangent:
        """The tangent of ``expr`` in every direction (chain rule over its free symbols)."""
        return self.combine(self.partials(expr))

    def combine(self, partials) -> _Tangent:
        return {w: sp.Add(*(d * t[w] for d, t in partials if t[w] != 0)) for w in self.wrt}

    def bind(self, name: str, tangent: _Tangent) -> list[tuple[sp.Symbol, sp.Basic]]:
        """Record ``name``'s tangent; the assignments of the directions that need a variable."""
        assigns, rec = [], {}
        for w in self.wrt:
            t = sp.sympify(tangent[w])
            if _direct(t):
                rec[w] = t
            else:
                s = sym(tangent_name(name, w))
                assigns.append((s, t))
                rec[w] = s
        self.tangents[name] = rec
        return assigns

    def materialize(self, name: str, wrt) -> list[tuple[sp.Symbol, sp.Basic]]:
        """Assignments giving ``name``'s tangents in ``wrt`` their own variables (where the frame
        holds a number or another variable), for code after a branch or a loop, or the outputs."""
        out = []
        for w in wrt:
            s = sym(tangent_name(name, w))
            if self.tangents[name][w] != s:
                out.append((s, self.tangents[name][w]))
        return out

    def copy(self) -> _Frame:
        return _Frame(
            self.wrt,
            {k: dict(v) for k, v in self.tangents.items()},
            {k: dict(v) for k, v in self.arrays.items()},
        )


@dataclass(frozen=True)
class _Derived:
    """A generated derivative kernel and the (output, direction) pairs whose derivative is
    identically zero (its callers use 0 instead)."""

    kernel: Kernel
    zero: frozenset


_NOTES = (
    "Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every "
    "direction in one pass; through an iteration, of the iterate it stops at."
)


@dataclass
class Differentiator:
    """Builds derivative kernels, each once, kept in :attr:`kernels` (name -> kernel) for the
    generator to place in ``<primal module>_jacobian``.

    - :meth:`jacobian` (then :meth:`build`): a public Jacobian kernel (outputs, then d output_i /
      d input_j row-major, a role kernel), which every caller differentiating the same kernel with
      respect to the same arguments shares.

    No derivative kernel checks its derivatives or its direction arguments for finiteness: an
    infinite derivative of an output the caller does not use must not fail the caller, and one the
    public API returns is its NUMERICAL_RANGE (runtime/api/jacobian.py). A public Jacobian checks its
    values as the map does; the others leave that to their callers, as JVP kernels always did.
    """

    kernels: dict[str, Kernel] = field(default_factory=dict)
    _jacobians: dict[tuple, dict[tuple[str, ...], _Derived]] = field(default_factory=dict)
    _jvps: dict[tuple, _Derived] = field(default_factory=dict)
    _public: dict[tuple, dict] = field(default_factory=dict)
    _pending: list = field(default_factory=list)
    #: (callee module, name, directions) -> the pattern its vector JVPs are widened to
    #: (:func:`widened`: one kernel for the patterns of every caller, e.g. the choices of a
    #: specialized option, instead of one per pattern).
    widen: dict[tuple, tuple] = field(default_factory=dict)
    #: The patterns asked for, by the same key (what :func:`widened` joins).
    asked: dict[tuple, set] = field(default_factory=dict)
    #: The derivative kernels of specialized kernels (one per choice: :meth:`_thin`).
    _per_choice: set = field(default_factory=set)

    # -- public ------------------------------------------------------------------------------------
    def jacobian(
        self,
        kernel: Kernel,
        wrt: tuple[str, ...],
        *,
        name: str,
        summary: str,
    ) -> None:
        """Declare the public Jacobian kernel ``name``: ``kernel``'s outputs and their derivatives
        ``d_<out>__<w>`` with respect to each ``w`` of ``wrt``, a role kernel of ``kernel``'s layout
        (values and derivatives checked to be finite). :meth:`build` builds it, after
        every declaration, so that each caller differentiating ``kernel`` with respect to ``wrt``
        (another map's zeroth iterate, the apex-return map's stance) calls it by its public name."""
        key = (kernel.module, kernel.name, tuple(wrt))
        if key in self._public:
            raise ValueError(f"two public Jacobians of {kernel.name} with respect to {wrt}")
        self._public[key] = {"name": name, "summary": summary, "layout": kernel.layout}
        self._pending.append((kernel, tuple(wrt)))

    def build(self) -> dict[str, Kernel]:
        """Build every declared public Jacobian (and the kernels it calls); :attr:`kernels`."""
        for kernel, wrt in self._pending:
            self._jacobian(kernel, wrt)
        self._pending.clear()
        return self.kernels

    # -- internal kernels ---------------------------------------------------------------------------
    def _jacobian(self, kernel: Kernel, wrt: tuple[str, ...]) -> _Derived:
        """The internal Jacobian of ``kernel`` with respect to ``wrt`` (unit directions)."""
        unknown = [a for a in wrt if a not in kernel.arg_names]
        if unknown:
            raise ValueError(f"kernel {kernel.name}: cannot differentiate with respect to {unknown}")
        memo = self._jacobians.setdefault((kernel.module, kernel.name), {})
        if wrt not in memo:
            public = self._public.get((kernel.module, kernel.name, wrt))
            seeds = {a: {w: sp.S.One if a == w else sp.S.Zero for w in wrt} for a in wrt}
            if public is None:
                name = f"{kernel.name}_jac" + ("" if wrt == kernel.arg_names else "_" + "_".join(wrt))
                if len(name) > MAX_NAME:  # the arguments by a digest: a call's line stays in the limit
                    digest = hashlib.sha256(repr(wrt).encode()).hexdigest()[:6]
                    name = f"{kernel.name}_jac{len(wrt)}_{digest}"
                summary = (
                    f"{kernel.summary.rstrip('.')}, and the derivatives of its outputs with respect to "
                    f"{', '.join(wrt)}."
                )
                public = {"name": name, "summary": summary, "layout": None}
            memo[wrt] = self._derive(
                kernel,
                wrt,
                seeds,
                name=public["name"],
                extra=(),
                summary=public["summary"],
                layout=public["layout"],
                check=public["layout"] is not None and kernel.check_outputs,
            )
        return memo[wrt]

    def _vector_jvp(self, kernel: Kernel, pattern: tuple[tuple[str, ...], ...]) -> _Derived:
        """``kernel``'s outputs and their derivatives along ``len(pattern)`` directions; direction
        ``j`` has along argument ``a`` the component ``pattern[j][i]`` of ``a = arg_names[i]``: "0",
        "1" or "s" (passed as the argument ``d_<a>__<j>``)."""
        key = (kernel.module, kernel.name, pattern)
        self.asked.setdefault(key[:2] + (len(pattern),), set()).add(pattern)
        if key not in self._jvps:
            dirs = tuple(str(j) for j in range(len(pattern)))
            seeds: dict[str, dict] = {}
            extra = []
            for j, row in zip(dirs, pattern, strict=True):
                for a, kind in zip(kernel.args, row, strict=True):
                    if kind == "s":
                        s = sym(tangent_name(a.name, j))
                        extra.append(Arg(s, f"direction {j}: its component along {a.name}"))
                    else:
                        s = sp.S.One if kind == "1" else sp.S.Zero
                    seeds.setdefault(a.name, {})[j] = s
            digest = hashlib.sha256(repr(pattern).encode()).hexdigest()[:6]
            self._jvps[key] = self._derive(
                kernel,
                dirs,
                seeds,
                name=f"{kernel.name}_jvp{len(dirs)}_{digest}",
                extra=tuple(extra),
                summary=f"{kernel.summary.rstrip('.')}, and the derivatives of its outputs along "
                f"{len(dirs)} directions (d_<argument>__<j>: direction j's component along an argument; "
                f"the arguments not listed have a fixed component, 0 or 1).",
            )
        return self._jvps[key]

    def _derive(
        self, kernel: Kernel, dirs: tuple, seeds: dict, *, name, extra, summary, layout=None, check=False
    ) -> _Derived:
        frame = _Frame(dirs, {})
        for a in kernel.args:
            frame.tangents[a.name] = {w: seeds.get(a.name, {}).get(w, sp.S.Zero) for w in dirs}
        ctx = _Ctx(self, frame)
        steps = ctx.steps(kernel.steps)
        finals: list = []
        zero = set()
        for f in kernel.outputs.fields():
            for w in dirs:
                if ctx.frame.tangents[f.name][w] == 0:
                    zero.add((f.name, w))
            finals += ctx.frame.materialize(f.name, dirs)
        if finals:
            steps += (Stage(tuple(finals), comment="derivatives of the outputs"),)
        fields = derivative_fields(kernel.outputs, dirs)
        module = f"{kernel.module}_jacobian"
        needed = set(kernel.outputs.names()) | {f.name for f in fields}
        steps = prune(prune_rows(prune(steps, needed)), needed)
        steps = Outliner(name, module, self._add).steps(steps, needed)
        # the arguments and the outputs are the differentiated kernel's: its docstring lists them
        ref = f":func:`{kernel.module}.{kernel.name}`"
        doc_args = f"those of {ref}, in its order"
        passed = {a.name for a in kernel.args for j in dirs if seeds.get(a.name, {}).get(j, 0) not in (0, 1)}
        along = [a.name for a in kernel.args if a.name in passed]
        if along:
            doc_args += (
                f"; then the components d_<argument>__<j> of each direction j (0 to {len(dirs) - 1}) "
                f"along {', '.join(along)}"
            )
        values = (("<output>", f"each output of {ref}, in its order"),)
        if dirs == (None,):
            block = ("<output>__tan", "the derivative of each output above along the direction, in order")
        else:
            over = "direction" if dirs[0] == "0" else "argument"
            block = (
                f"d_<output>__<{over}>",
                f"d output / d {over} for each output above and {over} {', '.join(dirs)} (row-major)",
            )
        out = Kernel(
            name=name,
            summary=summary,
            equations=kernel.equations,
            args=kernel.args + tuple(extra),
            steps=steps,
            outputs=Group("", kernel.outputs.items + fields),
            status=kernel.status,
            layout=layout,
            notes=_NOTES,
            module=module,
            check_inputs=kernel.check_inputs,
            check_outputs=check,
            inline_rows=kernel.inline_rows and layout is not None,
            unchecked=tuple(a.name for a in extra) + tuple(f.name for f in fields),
            doc_args=doc_args + ".",
            doc_returns=values + (block,),
            unroll_nodes=False,
        )
        suffix = choice_of(kernel)
        if suffix:
            out = self._thin(out, suffix)
        self._add(out)
        # a dense_tangent kernel's callers read every entry (derive/ir.py): none is zero to them
        return _Derived(out, frozenset() if kernel.dense_tangent else frozenset(zero))

    def _thin(self, k: Kernel, suffix: str) -> Kernel:
        """A per-choice derivative kernel (of a kernel specialized for ``suffix``'s choice) whose
        steps after its last call of another per-choice kernel are the same for several choices:
        those steps (the chain rule through the choice's callees, the rest of the map) become one
        kernel ``<name without the suffix>_tail_<digest>``, shared by every choice with the same
        code, and the per-choice kernel returns its result (a tail :class:`~.ir.Call`)."""
        self._per_choice.add(k.name)
        steps = k.steps
        calls = [i for i, s in enumerate(steps) if isinstance(s, Call) and s.kernel.name in self._per_choice]
        if not calls or not k.status or not k.name.endswith(suffix):
            return k
        tail = steps[calls[-1] + 1 :]
        if not all(isinstance(s, Stage | Call) for s in tail) or _size(tail) < TAIL_SIZE:
            return k
        inside = defined(tail)
        inputs = sorted((used(tail) - inside) | (set(k.output_names) - inside))
        digest = hashlib.sha256(repr((_fingerprint(tail), inputs, k.check_outputs)).encode()).hexdigest()[:6]
        base = k.name.removesuffix(suffix)
        name = f"{base}_tail_{digest}"
        helper = self.kernels.get(name)
        if helper is None:
            helper = replace(
                k,
                name=name,
                summary=f"The code of {base}'s kernels per choice after their choice's own calls, shared by "
                "the choices with the same code (derive/tangent.py).",
                args=tuple(Arg(sym(n), "the caller's variable of the same name") for n in inputs),
                steps=tail,
                layout=None,
                check_inputs=False,
                doc_args="the per-choice caller's variables of the same names.",
            )
            self._add(helper)
        call = Call(
            helper, {n: sym(n) for n in inputs}, {}, comment="the code shared between choices", tail=True
        )
        return replace(k, steps=steps[: calls[-1] + 1] + (call,), check_outputs=False)

    def _add(self, kernel: Kernel) -> None:
        if kernel.name in self.kernels:
            raise ValueError(f"two generated kernels named {kernel.name}")
        self.kernels[kernel.name] = kernel

    def _for_call(self, callee: Kernel, active: tuple[str, ...], dirs: tuple) -> tuple[str, object]:
        """How a call differentiates ``callee``: ("jacobian", wrt) or ("jvp", None) (module docstring)."""
        memo = self._jacobians.get((callee.module, callee.name), {})
        fewest = min(len(active), len(dirs))
        supersets = sorted((len(b), b) for b in memo if set(active) <= set(b) and len(b) <= fewest + 1)
        if supersets:
            return "jacobian", supersets[0][1]
        if len(active) <= len(dirs):
            return "jacobian", active
        return "jvp", None


def widened(asked: dict[tuple, set]) -> dict[tuple, tuple]:
    """For each callee and number of directions asked for more than one pattern (a
    :attr:`Differentiator.asked`), their join: an entry all of them agree on is kept ("0" or "1",
    built in), any other passed ("s")."""
    out = {}
    for key, patterns in asked.items():
        if len(patterns) > 1:
            rows = zip(*sorted(patterns), strict=True)
            out[key] = tuple(
                tuple(e[0] if len(set(e)) == 1 else "s" for e in zip(*row, strict=True)) for row in rows
            )
    return out


#: The generic direction of the tangent code a loop runs once per direction (:meth:`_Ctx.looped`).
_J = "j"


#: A loop with at least this many assignments per pass (its steps' assignments and bindings, a
#: switch's largest branch, its updates) gets its tangent code written once and run per direction
#: (unless it declares ``per_direction=False``); a smaller one one variable per tangent and
#: direction. Measured 2026-12-05 (benchmarks/bench_versions.py, 2-core machine, load 1.1) against
#: the same loops unrolled: the gravity maps' loops of 21-23 assignments per direction, with the
#: direction array on the stack, 0.92-0.98x the Jacobian batch's time and 340 fewer generated
#: lines; geyer-vs's loop (no pass by default) 1.07-1.12x (one thread): it declares
#: ``per_direction=False``.
LOOPED_SIZE = 20


#: A Jacobian kernel's name lists the arguments it differentiates by up to this many characters;
#: a longer one names them by a digest (``<kernel>_jac<count>_<digest>``).
MAX_NAME = 80

#: A per-choice derivative kernel's tail of at least this many assignments is shared
#: (:meth:`Differentiator._thin`).
TAIL_SIZE = 8


def _fingerprint(x):
    """What identifies IR code (steps, expressions), a callee by its module and name: equal for the
    same code, for a digest."""
    if isinstance(x, Kernel):
        return ("kernel", x.module, x.name)
    if is_dataclass(x):
        return (type(x).__name__, *(_fingerprint(getattr(x, f.name)) for f in fields(x)))
    if isinstance(x, tuple | list):
        return tuple(_fingerprint(e) for e in x)
    if isinstance(x, Mapping):
        return tuple(sorted((k, _fingerprint(v)) for k, v in x.items()))
    return sp.srepr(x) if isinstance(x, sp.Basic) else repr(x)


def _size(steps) -> int:
    n = 0
    for s in steps:
        if isinstance(s, Stage):
            n += len(s.assignments)
        elif isinstance(s, Call):
            n += len(s.bind)
        elif isinstance(s, Switch):
            n += max((_size(b) for _, b in s.cases), default=0)
        elif isinstance(s, Iterate):
            n += _size(s.evaluate) + _size(s.body) + len(s.update)
    return n


def _straight(steps) -> bool:
    """Steps without a loop or a branch: stages and calls."""
    return all(isinstance(s, (Stage, Call)) for s in steps)


def _loopable(steps) -> bool:
    """Steps whose tangent code can run per direction (:meth:`_Ctx.split`): stages, calls and
    switches of such steps."""
    return all(
        isinstance(s, (Stage, Call)) or (isinstance(s, Switch) and all(_loopable(b) for _, b in s.cases))
        for s in steps
    )


@dataclass
class _Ctx:
    diff: Differentiator
    frame: _Frame
    #: counters shared by the contexts of one derivative kernel: partial derivatives given variables
    #: of their own (``_pd__<n>``) and rows of the direction array ``_T``
    counters: dict = field(default_factory=lambda: {"pd": 0, "row": 0})
    #: differentiating along the one generic direction of a loop's per-direction tangent code
    generic: bool = False

    def row(self) -> int:
        self.counters["row"] += 1
        return self.counters["row"] - 1

    def steps(self, steps) -> tuple:
        out: list = []
        steps = tuple(steps)
        i = 0
        while i < len(steps):
            step = steps[i]
            i += 1
            if isinstance(step, Stage):
                out.append(self.stage(step))
            elif isinstance(step, Call):
                out.extend(self.call(step))
            elif isinstance(step, Iterate):
                # the steps right after a loop, without a loop: per direction too, with the loop's
                tail = []
                while i < len(steps) and _straight((steps[i],)):
                    tail.append(steps[i])
                    i += 1
                out.extend(self.iterate(step, tuple(tail)))
            elif isinstance(step, Switch):
                out.append(self.switch(step))
            elif isinstance(step, Lookup):
                out.append(self.lookup(step))
            elif isinstance(step, Nodes):
                out.append(self.nodes(step))
            elif isinstance(step, Reduce):
                out.extend(self.reduce(step))
            else:
                raise TypeError(f"cannot differentiate a {type(step).__name__}")
        return tuple(out)

    # -- node arrays (derive/ir.py: Lookup, Nodes, Reduce) ------------------------------------------
    def lookup(self, lk: Lookup) -> Lookup:
        """Tables are constants: no tangent."""
        for name, tables in lk.tables:
            first = tables[0][1]
            if isinstance(first, tuple):
                self.frame.arrays[name] = dict.fromkeys(self.frame.wrt)
            else:
                self.frame.tangents[name] = {w: sp.S.Zero for w in self.frame.wrt}
        return lk

    def _array_tangent(self, array: str, w) -> str | None:
        return self.frame.arrays.get(array, {}).get(w)

    def nodes(self, nd: Nodes) -> Nodes:
        """The loop with its tangents, element by element: a read's tangent from the array's
        tangent array (one per direction), a sum's the same sum of the tangent array, the stages
        differentiated as anywhere, each write's tangent into the written array's tangent array
        (none where it is zero in every node)."""
        outer = self.frame
        wrt = outer.wrt
        self.frame = inner = outer.copy()
        reads, sums = list(nd.reads), list(nd.sums)
        for local, array in nd.reads:
            t = {}
            for w in wrt:
                ta = self._array_tangent(array, w)
                t[w] = sp.S.Zero if ta is None else sym(tangent_name(local.name, w))
                if ta is not None:
                    reads.append((t[w], ta))
            inner.tangents[local.name] = t
        for local, matrix, array in nd.sums:
            t = {}
            for w in wrt:
                ta = self._array_tangent(array, w)
                t[w] = sp.S.Zero if ta is None else sym(tangent_name(local.name, w))
                if ta is not None:
                    sums.append((t[w], matrix, ta))
            inner.tangents[local.name] = t
        steps = tuple(self.stage(st) for st in nd.steps)
        writes = list(nd.writes)
        arrays = {}
        for e, array in nd.writes:
            t = inner.of(e)
            arrays[array] = {}
            for w in wrt:
                if t[w] != 0:
                    name = tangent_name(array, w)
                    writes.append((t[w], name))
                    arrays[array][w] = name
                else:
                    arrays[array][w] = None
        self.frame = outer
        outer.arrays.update(arrays)
        return Nodes(nd.count, tuple(reads), tuple(sums), steps, tuple(writes), nd.comment)

    def reduce(self, rd: Reduce) -> list:
        """The sum, and the same sum of each tangent array of the summed array."""
        out: list = [rd]
        t = {}
        for w in self.frame.wrt:
            ta = self._array_tangent(rd.array, w)
            if ta is None:
                t[w] = sp.S.Zero
            else:
                t[w] = sym(tangent_name(rd.name.name, w))
                out.append(Reduce(t[w], rd.weights, ta, rd.count))
        self.frame.tangents[rd.name.name] = t
        return out

    def zero_arrays(self, names: list[str], count) -> tuple[Nodes, ...]:
        """Node arrays of zeros (the tangents of an iteration's state where its start or update has
        none), in one node loop."""
        if not names:
            return ()
        return (
            Nodes(count, (), (), (), tuple((sp.S.Zero, n) for n in names), comment="tangents that are 0"),
        )

    def parts(self, st: Stage) -> list[tuple[list, list]]:
        """For each assignment: its value and the partial derivatives used in two or more directions
        (in the generic direction: every one that is not a number or a variable) as variables of
        their own (``_pd__<n>``); its tangents, sum over x of (d f / d x) times the tangent of x."""
        out = []
        for s, expr in st.assignments:
            values = [(s, expr)]
            partials = []
            for d, t in self.frame.partials(expr):
                if not _direct(d) and (self.generic or sum(1 for v in t.values() if v != 0) > 1):
                    p = sym(f"_pd__{self.counters['pd']}")
                    self.counters["pd"] += 1
                    values.append((p, d))
                    d = p
                partials.append((d, t))
            out.append((values, self.frame.bind(s.name, self.frame.combine(partials))))
        return out

    def stage(self, st: Stage) -> Stage:
        """Each assignment, its partial derivatives, then its tangents (:meth:`parts`); the partial
        derivatives and the tangents stay variables for the later assignments (the chain rule's
        products, not expanded)."""
        assigns, opaque = [], []
        for values, tangents in self.parts(st):
            assigns += values + tangents
            opaque += [p.name for p, _ in values[1:]] + [t.name for t, _ in tangents]
        return Stage(tuple(assigns), st.guards, st.comment, opaque=tuple(opaque), zero=st.zero)

    def split(self, steps) -> tuple[list, list]:
        """Generic direction: the steps' values (stages with their partial derivatives, calls of the
        callees' Jacobians) and their tangent code (stages), apart."""
        values, tangents = [], []
        for step in steps:
            if isinstance(step, Stage):
                groups = self.parts(step)
                vals = [a for v, _ in groups for a in v]
                partial_names = tuple(p.name for v, _ in groups for p, _ in v[1:])
                values.append(
                    Stage(tuple(vals), step.guards, step.comment, opaque=partial_names, zero=step.zero)
                )
                assigns = tuple(a for _, t in groups for a in t)
                if assigns:
                    tangents.append(
                        Stage(
                            assigns,
                            comment=step.comment,
                            opaque=tuple(s.name for s, _ in assigns),
                            zero=step.zero,
                        )
                    )
            elif isinstance(step, Call):
                for part in self.call(step):
                    (values if isinstance(part, Call) else tangents).append(part)
            elif isinstance(step, Switch):
                vals, tans = self.split_switch(step)
                values.append(vals)
                if any(branch for _, branch in tans.cases):
                    tangents.append(tans)
            else:
                raise TypeError(f"no per-direction tangent code for a {type(step).__name__}")
        return values, tangents

    def call(self, c: Call) -> list:
        """The chain rule through a derivative of the callee (module docstring)."""
        callee = c.kernel
        wrt = self.frame.wrt
        arg_t = {a: self.frame.of(c.args[a]) for a in callee.arg_names}
        active = tuple(a for a in callee.arg_names if any(v != 0 for v in arg_t[a].values()))
        dirs = tuple(w for w in wrt if any(arg_t[a][w] != 0 for a in active))
        if not active or not c.bind:
            for local in c.bind.values():
                self.frame.bind(local, {w: sp.S.Zero for w in wrt})
            return [c]
        if callee.external:
            return self.external_call(c, arg_t, active)
        # (in the generic direction always the callee's Jacobian: its tangents are values there)
        how, by = self.diff._for_call(callee, active, active if self.generic else dirs)
        if how == "jacobian":
            return self._through_jacobian(c, arg_t, active, by)
        return self._through_jvp(c, arg_t, dirs)

    def _through_jacobian(self, c: Call, arg_t, active, by) -> list:
        derived = self.diff._jacobian(c.kernel, by)
        bind = dict(c.bind)
        entries: dict[str, list] = {}
        for out, local in c.bind.items():
            entries[local] = []
            for a in active:
                if (out, a) not in derived.zero:
                    name = _entry_name(local, a)
                    bind[tangent_name(out, a)] = name
                    entries[local].append((sym(name), a))
        steps: list = [Call(derived.kernel, dict(c.args), bind, comment=c.comment)]
        chain = []
        for local, row in entries.items():
            tangent = {w: sp.Add(*(j * arg_t[a][w] for j, a in row)) for w in self.frame.wrt}
            chain += self.frame.bind(local, tangent)
        if chain:
            # named without a choice suffix: the same code for every choice (Differentiator._thin)
            generic = c.kernel.name.removesuffix(choice_of(c.kernel))
            steps.append(Stage(tuple(chain), comment=f"chain rule through {generic}"))
        return steps

    def _through_jvp(self, c: Call, arg_t, dirs) -> list:
        callee = c.kernel

        def kind(t):
            return "0" if t == 0 else "1" if t == 1 else "s"

        pattern = tuple(tuple(kind(arg_t[a][w]) for a in callee.arg_names) for w in dirs)
        wide = self.diff.widen.get((callee.module, callee.name, len(pattern)), pattern)
        if any(x != y != "s" for p, q in zip(pattern, wide, strict=True) for x, y in zip(p, q, strict=True)):
            raise ValueError(f"vector JVP of {callee.name}: pattern {pattern} is not within {wide}")
        pattern = wide
        derived = self.diff._vector_jvp(callee, pattern)
        args = dict(c.args)
        for j, (w, row) in enumerate(zip(dirs, pattern, strict=True)):
            for a, k in zip(callee.arg_names, row, strict=True):
                if k == "s":
                    args[tangent_name(a, str(j))] = arg_t[a][w]
        bind = dict(c.bind)
        for out, local in c.bind.items():
            tangent = {w: sp.S.Zero for w in self.frame.wrt}
            for j, w in enumerate(dirs):
                if (out, str(j)) not in derived.zero:
                    bind[tangent_name(out, str(j))] = tangent_name(local, w)
                    tangent[w] = sym(tangent_name(local, w))
            self.frame.tangents[local] = tangent
        return [Call(derived.kernel, args, bind, comment=c.comment)]

    def external_call(self, c: Call, arg_t: dict[str, _Tangent], active: tuple[str, ...]) -> list:
        """A hand-written callee (``Kernel.external``): its own Jacobian kernel gives d output / d
        argument, and each bound output's tangent is that row times the arguments' tangents."""
        callee = c.kernel
        if callee.jacobian is None:
            raise ValueError(
                f"external kernel {callee.name} has no Jacobian: cannot differentiate a call of it"
            )
        missing = [a for a in active if a not in callee.jacobian_wrt]
        if missing:
            raise ValueError(
                f"external kernel {callee.name}: its Jacobian is with respect to "
                f"{list(callee.jacobian_wrt)}, "
                f"not {missing}"
            )
        bind = dict(c.bind)
        chain = []
        for out, local in c.bind.items():
            entries = []
            for a in active:
                entry = sym(f"dext_{local}__{a}")
                bind[tangent_name(out, a)] = entry.name
                entries.append((entry, a))
            tangent = {w: sp.Add(*(j * arg_t[a][w] for j, a in entries)) for w in self.frame.wrt}
            chain += self.frame.bind(local, tangent)
        steps: list = [Call(callee.jacobian, dict(c.args), bind, comment=c.comment)]
        if chain:
            steps.append(
                Stage(
                    tuple(chain),
                    comment=f"tangents of {callee.name}'s outputs: its Jacobian times the directions",
                )
            )
        return steps

    def iterate(self, it: Iterate, tail: tuple = ()) -> list:
        """The loop (and the stages and calls of its ``tail``) with its tangents: written once and
        run per direction where the loop's steps are stages and calls and there are several
        directions (:meth:`looped`), else one variable per tangent and direction, carried through
        the passes (:attr:`~.ir.Iterate.carry`)."""
        size = _size(it.evaluate + it.body) + len(it.update)
        if (
            it.per_direction is not False
            and _loopable(it.evaluate + it.body)
            and size >= LOOPED_SIZE
            and not self.generic
            and len(self.frame.wrt) > 1
        ):
            return self.looped(it, tail)
        return [*self.unrolled(it), *self.steps(tail)]

    def _reach(self, it: Iterate) -> tuple[set[str], tuple]:
        """The names from before the loop it reads, and the directions that reach it through them."""
        names = [s for s, _ in it.state] + [c[0] for c in it.carry]
        inner = {s.name for s in names} | {it.count.name} | {a[0] for a in it.arrays + it.array_carry}
        reads = used(it.evaluate + it.body) - inner
        reads |= {a[1] for a in it.arrays + it.array_carry}
        exprs = [e for _, e in it.state] + list(it.update) + [e for c in it.carry for e in (c[1], c[2])]
        for e in (*exprs, it.max_iter, it.tol, *it.scales):
            reads |= {s.name for s in sp.sympify(e).free_symbols} - inner
        outer = self.frame

        def reaches(n, w) -> bool:
            return outer.tangents.get(n, {}).get(w, 0) != 0 or outer.arrays.get(n, {}).get(w) is not None

        reach = tuple(w for w in outer.wrt if any(reaches(n, w) for n in reads))
        return reads, reach

    def looped(self, it: Iterate, tail: tuple = ()) -> list:
        """Values once, tangent code once: each pass computes the values and partial derivatives,
        then runs its tangent code once per direction (:class:`~.ir.Directions`) on the state's
        tangents in the rows of the direction array ``_T``; the next state's tangents overwrite
        them (a direction reads its column before it writes it). Before the loop the tangents of
        what it reads and of its initial values are stored in rows; after it the state's and the
        evaluated names' tangents are loaded into a variable per direction."""
        outer = self.frame
        wrt = outer.wrt
        reads, reach = self._reach(it)
        if not reach:
            return [*self.unrolled(it), *self.steps(tail)]
        names = [s for s, _ in it.state] + [c[0] for c in it.carry]
        inits = [init for _, init in it.state] + [c[1] for c in it.carry]
        updates = list(it.update) + [c[2] for c in it.carry]
        gen = _Frame((_J,), {})
        pre: list = []
        rows: list[tuple[sp.Symbol, int]] = []
        # what the loop and its tail read from before them (the tail: besides what the loop defines)
        inner = {s.name for s in names} | {it.count.name} | set(visible(it.evaluate))
        reads = reads | (used(tail) - inner - defined(tail))
        for x in sorted(reads):
            t = outer.tangents.get(x)
            if t is not None and any(v != 0 for v in t.values()):
                row = self.row()
                pre.append(Store(row, tuple(t[w] for w in wrt)))
                gen.tangents[x] = {_J: sym(tangent_name(x, _J))}
                rows.append((gen.tangents[x][_J], row))
        n = len(wrt)
        sub = _Ctx(self.diff, gen, self.counters, generic=True)
        # the initial values' tangents, per direction too, into the state's rows
        starts = [sym(f"{s.name}__start") for s in names]
        init_values, init_tangents = sub.split(
            (Stage(tuple(zip(starts, inits, strict=True)), comment="the initial values"),)
        )
        state_rows = {s.name: self.row() for s in names}
        pre += init_values
        pre.append(
            Directions(
                n,
                tuple(rows),
                tuple(init_tangents),
                tuple(
                    (sub.frame.tangents[x.name][_J], state_rows[s.name])
                    for s, x in zip(names, starts, strict=True)
                    if sub.frame.tangents[x.name][_J] != 0
                ),
                comment="the initial values' tangents, once per direction",
            )
        )
        zero_starts = [s for s, x in zip(names, starts, strict=True) if sub.frame.tangents[x.name][_J] == 0]
        if zero_starts:
            pre.append(Directions(n, (), (), tuple((sp.S.Zero, state_rows[s.name]) for s in zero_starts)))
        for s in names:
            sub.frame.tangents[s.name] = {_J: sym(tangent_name(s.name, _J))}
            rows.append((sub.frame.tangents[s.name][_J], state_rows[s.name]))
        sub.frame.tangents[it.count.name] = {_J: sp.S.Zero}
        ev_values, ev_tangents = sub.split(it.evaluate)
        evaluated = [e for e in visible(it.evaluate) if sub.frame.tangents[e][_J] != 0]
        ev_rows = {e: self.row() for e in evaluated}
        evaluate = tuple(ev_values) + (
            Directions(
                n,
                tuple(rows),
                tuple(ev_tangents),
                tuple((sub.frame.tangents[e][_J], ev_rows[e]) for e in evaluated),
                comment="the evaluation's tangents, once per direction",
            ),
        )
        read_evaluated = tuple((sym(tangent_name(e, _J)), ev_rows[e]) for e in evaluated)
        for e in evaluated:  # the body reads them from their rows
            sub.frame.tangents[e] = {_J: sym(tangent_name(e, _J))}
        nxt = [sym(f"{s.name}__next") for s in names]
        body_values, body_tangents = sub.split(
            it.body + (Stage(tuple(zip(nxt, updates, strict=True)), comment="next values"),)
        )
        body = tuple(body_values) + (
            Directions(
                n,
                tuple(rows) + read_evaluated,
                tuple(body_tangents),
                tuple(
                    (sub.frame.tangents[x.name][_J], state_rows[s.name])
                    for s, x in zip(names, nxt, strict=True)
                ),
                comment="the next state's tangents, once per direction",
            ),
        )
        k = len(it.state)
        loop = replace(
            it,
            body=body,
            update=tuple(nxt[:k]),
            carry=tuple((c[0], c[1], x) for c, x in zip(it.carry, nxt[k:], strict=True)),
            evaluate=evaluate,
        )
        # the steps after the loop: values, then their tangents per direction too
        after: list = []
        tail_rows = {}
        if tail:
            for s in names:  # the state's tangents are in its rows, as the evaluation's
                sub.frame.tangents[s.name] = {_J: sym(tangent_name(s.name, _J))}
            tail_values, tail_tangents = sub.split(tail)
            defined_after = [x for x in visible(tail) if sub.frame.tangents[x][_J] != 0]
            tail_rows = {x: self.row() for x in defined_after}
            after = tail_values + [
                Directions(
                    n,
                    tuple(rows) + read_evaluated,
                    tuple(tail_tangents),
                    tuple((sub.frame.tangents[x][_J], tail_rows[x]) for x in defined_after),
                    comment="their tangents, once per direction",
                )
            ]
        # then a variable per direction for the tangents of what the loop and its tail define
        self.frame = outer.copy()
        post = []
        loaded_rows = [(s.name, state_rows[s.name]) for s in names] + list(ev_rows.items())
        for name, row in loaded_rows + list(tail_rows.items()):
            loaded = tuple(sym(tangent_name(name, w)) for w in wrt)
            post.append(Load(row, loaded))
            self.frame.tangents[name] = dict(zip(wrt, loaded, strict=True))
        zero = {w: sp.S.Zero for w in wrt}
        for e in visible(it.evaluate) + visible(tail):
            if e not in ev_rows and e not in tail_rows:
                self.frame.tangents[e] = dict(zero)
        self.frame.tangents[it.count.name] = dict(zero)
        return pre + [loop] + after + post

    def unrolled(self, it: Iterate) -> list:
        outer = self.frame
        wrt = outer.wrt
        names = [s for s, _ in it.state] + [c[0] for c in it.carry]
        inits = [init for _, init in it.state] + [c[1] for c in it.carry]
        updates = list(it.update) + [c[2] for c in it.carry]
        # the directions that reach the loop: through what it reads from before it
        _, reach = self._reach(it)
        init_t = [outer.of(e) for e in inits]
        # the node arrays of the state: their tangent arrays start as their initial arrays' (zeros
        # where those have none)
        arrays = [(a, i, u) for a, i, u, _ in it.arrays] + list(it.array_carry)
        zeros: list[str] = []
        array_init = {}
        for a, init, _ in arrays:
            array_init[a] = {}
            for w in reach:
                ta = outer.arrays.get(init, {}).get(w)
                if ta is None:
                    ta = tangent_name(init, w)
                    zeros.append(ta)
                array_init[a][w] = ta
        pre = list(self.zero_arrays(zeros, it.nodes))
        self.frame = outer.copy()
        for s in names:
            self.frame.tangents[s.name] = {w: sym(tangent_name(s.name, w)) if w in reach else 0 for w in wrt}
        for a, _, _ in arrays:
            self.frame.arrays[a] = {w: tangent_name(a, w) if w in reach else None for w in wrt}
        self.frame.tangents[it.count.name] = {w: sp.S.Zero for w in wrt}
        evaluate = self.steps(it.evaluate)
        evaluated = {
            n: dict(self.frame.tangents[n]) for n in visible(it.evaluate) if n in self.frame.tangents
        }
        evaluated_arrays = {
            n: dict(self.frame.arrays[n]) for n in visible(it.evaluate) if n in self.frame.arrays
        }
        body = self.steps(it.body)
        array_carry = []
        zeros = []
        for a, _, upd in arrays:
            for w in reach:
                tu = self.frame.arrays.get(upd, {}).get(w)
                if tu is None:
                    tu = tangent_name(upd, w)
                    zeros.append(tu)
                array_carry.append((tangent_name(a, w), array_init[a][w], tu))
        body += self.zero_arrays(zeros, it.nodes)
        # the next values and their tangents as a stage of the body (one CSE, partials shared)
        nxt = [sym(f"{s.name}__next") for s in names]
        body += (self.stage(Stage(tuple(zip(nxt, updates, strict=True)), comment="next values")),)
        update_t = [self.frame.tangents[n.name] for n in nxt]
        carry = []
        for s, t0, t in zip(names, init_t, update_t, strict=True):
            for w in wrt:
                if w in reach:
                    carry.append((sym(tangent_name(s.name, w)), t0[w], t[w]))
                elif t[w] != 0 or t0[w] != 0:
                    raise AssertionError(f"{s.name}: a tangent in {w}, which does not reach the loop")
        # after the loop: the state, the carried variables, the count and what the loop evaluates
        self.frame = outer.copy()
        for s in names:
            self.frame.tangents[s.name] = {w: sym(tangent_name(s.name, w)) if w in reach else 0 for w in wrt}
        self.frame.tangents[it.count.name] = {w: sp.S.Zero for w in wrt}
        self.frame.tangents.update(evaluated)
        for a, _, _ in arrays:
            self.frame.arrays[a] = {w: tangent_name(a, w) if w in reach else None for w in wrt}
        self.frame.arrays.update(evaluated_arrays)
        k = len(it.state)
        loop = replace(
            it,
            body=body,
            update=tuple(nxt[:k]),
            carry=tuple((c[0], c[1], n) for c, n in zip(it.carry, nxt[k:], strict=True)) + tuple(carry),
            evaluate=evaluate,
            array_carry=it.array_carry + tuple(array_carry),
        )
        return pre + [loop]

    def switch(self, sw: Switch) -> Switch:
        (out,) = self._branches(sw, lambda steps: (self.steps(steps),))
        return out

    def split_switch(self, sw: Switch) -> tuple[Switch, Switch]:
        """Generic direction: the switch of the branches' values and the switch of their tangent
        code (:meth:`split`), on the same selector (an option: the same branch both times)."""
        return self._branches(sw, lambda steps: tuple(tuple(part) for part in self.split(steps)))

    def _branches(self, sw: Switch, differentiate) -> tuple[Switch, ...]:
        """Each branch differentiated by ``differentiate`` (its steps -> one or more step groups, the
        last of which holds the tangent code), then the tangents every branch defines named alike
        (in the last group of each branch): one switch per group."""
        before = self.frame
        branches = []
        for value, steps in sw.cases:
            self.frame = before.copy()
            groups = differentiate(steps)
            branches.append((value, groups, self.frame))
        defined = [set(f.tangents) - set(before.tangents) for _, _, f in branches]
        common = sorted(set.intersection(*defined)) if defined else []
        wrt = before.wrt
        merged = before.copy()
        for name in common:
            rec = {}
            for w in wrt:
                values = {f.tangents[name][w] for _, _, f in branches}
                # the same number in every branch is used in place; else each branch assigns it
                (one,) = values if len(values) == 1 else (None,)
                rec[w] = one if one is not None and one.is_Number else sym(tangent_name(name, w))
            merged.tangents[name] = rec
        n = len(branches[0][1]) if branches else 1
        cases: list[list] = [[] for _ in range(n)]
        for value, groups, f in branches:
            fill = []
            for name in common:
                fill += f.materialize(name, [w for w in wrt if not merged.tangents[name][w].is_Number])
            if fill:
                filled = Stage(tuple(fill), comment="tangents as every branch names them")
                groups = (*groups[:-1], groups[-1] + (filled,))
            for i, group in enumerate(groups):
                cases[i].append((value, group))
        self.frame = merged
        return tuple(Switch(sw.selector, tuple(c), sw.comment) for c in cases)


__all__ = ["Differentiator", "derivative_fields", "tangent_name"]
