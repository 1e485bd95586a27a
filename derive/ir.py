"""The kernel IR: what a generated numba function computes, declared as data.

A :class:`Kernel` is a scalar function of named :class:`Arg` s that runs a sequence of steps and
returns named outputs (a :class:`Group`, flattened to ``bottom_q_r``-style names) plus a status
code. Steps:

- :class:`Stage`: named assignments (one common-subexpression elimination over the stage, so
  temporaries are shared between its outputs, as PyDy does) followed by :class:`Guard` s. A guard
  is a condition the later steps need (a real square root, an arcsine argument in [-1, 1], ...);
  when it fails, or is NaN, the kernel returns NaN outputs and the guard's status code.
- :class:`Call`: calls another kernel, passing arguments **by the callee's argument names** and
  binding the callee's outputs **by name**; a failing callee status is propagated.
- :class:`Iterate`: a bounded fixed-point iteration on named state variables (at most ``max_iter``
  updates, stopping when every update moves by at most ``tol * scale``); what it ``evaluate`` s at
  every iterate stays visible after the loop, at the iterate it stops at.
- :class:`Switch`: branches on an integer option; every branch defines the same names.

Kernels never raise. :mod:`.lower` checks the declaration (every symbol an expression uses is an
input or the result of an earlier step; no name is defined twice) and turns it into template data.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy as sp

from .status import STATUS_CODES

STATUS = {name: code for name, code, _ in STATUS_CODES}


def real(sym: sp.Symbol) -> sp.Symbol:
    """The same-named symbol without sign assumptions, for guards SymPy must not fold to True."""
    return sp.Symbol(sym.name, real=True)


def positive(*syms: sp.Symbol) -> sp.Basic:
    """Condition: every symbol is > 0 (checked at run time, whatever its assumptions)."""
    return sp.And(*(real(s) > 0 for s in syms))


def sym(name: str) -> sp.Symbol:
    """A real symbol: the type of every kernel-local quantity."""
    return sp.Symbol(name, real=True)


@dataclass(frozen=True)
class Arg:
    """A kernel argument. ``domain`` (optional) must hold on entry, else status INVALID_INPUT."""

    symbol: sp.Symbol
    doc: str
    domain: sp.Basic | None = None

    def __post_init__(self):
        if self.domain in (sp.true, sp.false) or isinstance(self.domain, bool):
            # as for Guard: a domain folded through the symbol's assumptions would never be checked
            raise ValueError(f"the domain of argument {self.name} folds to the constant {self.domain}")

    @property
    def name(self) -> str:
        return self.symbol.name


@dataclass(frozen=True)
class Field:
    """One named scalar output. ``odd``: the output changes sign under the model's mirror symmetry
    x -> -x (a leg angle or angle rate, a horizontal speed or distance, an angular impulse); an even
    one keeps its value. Running toward -x is the mirror image of running toward +x."""

    name: str
    doc: str
    unit: str = ""
    odd: bool = False


@dataclass(frozen=True)
class Group:
    """Named outputs, possibly nested: ``Group("bottom", POLAR)`` flattens to ``bottom_q_r``, ..."""

    name: str
    items: tuple[Field | Group, ...]
    doc: str = ""

    def fields(self, prefix: str = "") -> tuple[Field, ...]:
        """The flattened fields, each named ``<prefix><group>_<field>`` (the root group adds nothing)."""
        pre = f"{prefix}{self.name}_" if self.name else prefix
        out: list[Field] = []
        for item in self.items:
            if isinstance(item, Group):
                out.extend(item.fields(pre))
            else:
                out.append(Field(pre + item.name, item.doc, item.unit, item.odd))
        return tuple(out)

    def names(self) -> tuple[str, ...]:
        return tuple(f.name for f in self.fields())

    def subgroups(self, prefix: str = "") -> dict[str, tuple[str, ...]]:
        """Flattened name of every nested group -> the flattened names of its fields."""
        pre = f"{prefix}{self.name}_" if self.name else prefix
        out: dict[str, tuple[str, ...]] = {}
        for item in self.items:
            if isinstance(item, Group):
                out[pre + item.name] = tuple(f.name for f in item.fields(pre))
                out.update(item.subgroups(pre))
        return out

    def __add__(self, other: Group) -> Group:
        return Group(self.name, self.items + other.items, self.doc)


@dataclass(frozen=True)
class Guard:
    """A condition that must hold (NaN counts as failure); else NaN outputs and ``status``."""

    condition: sp.Basic
    status: str
    doc: str = ""

    def __post_init__(self):
        if self.status not in STATUS:
            raise ValueError(f"unknown status {self.status!r}")
        if self.condition in (sp.true, sp.false) or isinstance(self.condition, bool):
            # SymPy folded the condition through symbol assumptions (e.g. a positive=True symbol):
            # the run-time check would vanish. Build it from real(...) symbols instead.
            raise ValueError(f"guard for {self.status} folds to the constant {self.condition}")


@dataclass(frozen=True)
class Stage:
    """Named assignments (in order; a later one may use an earlier one), then guards.

    The stage's one CSE sees an assignment that uses an earlier one of the stage with that one
    inlined, except for the ``opaque`` names, which later assignments read as variables (a
    derivative stage's tangents: inlining them would expand the chain rule's products).
    """

    assignments: tuple[tuple[sp.Symbol, sp.Basic], ...]
    guards: tuple[Guard, ...] = ()
    comment: str = ""
    opaque: tuple[str, ...] = ()
    #: Inputs that are exactly 0 wherever the stage runs (a branch taken on that): the generated
    #: code evaluates its assignments at 0, after derive/tangent.py has differentiated them, so a
    #: first-order term in such an input gives its derivative and costs the values nothing (a leg
    #: held still, derive/model/flight.py).
    zero: tuple[sp.Symbol, ...] = ()


@dataclass(frozen=True)
class Call:
    """Call ``kernel`` with ``args`` (callee argument name -> expression) and bind its outputs.

    ``bind`` maps a callee output name to the caller's name for it; outputs not named are
    dropped. A non-OK callee status is returned as the caller's status.

    ``tail``: the caller's last step, whose result the caller returns as its own (the callee has
    the caller's outputs, in order, and a status; ``bind`` is empty): a per-choice derivative
    kernel ending in the code it shares with the other choices (:mod:`.tangent`).
    """

    kernel: Kernel
    args: Mapping[str, sp.Basic]
    bind: Mapping[str, str]
    comment: str = ""
    tail: bool = False


@dataclass(frozen=True)
class Iterate:
    """Bounded fixed-point iteration ``x <- update(x)`` on the state variables.

    ``state`` gives each variable and its initial value. Each pass runs ``body`` (which sees the
    current state) and computes ``update`` (the new value of every state variable, in the same
    order). The loop stops after a pass in which every variable moved by at most ``tol`` times its
    ``scales`` entry (a positive expression in the units of that variable), or after ``max_iter``
    passes; then ``fail_status`` (if set) is returned when ``tol > 0``. With ``tol = 0`` it runs
    exactly ``max_iter`` passes; with ``max_iter = 0`` none (the initial values stand, no failure).
    After the loop the state variables and ``count`` (the number of passes, a float) are visible,
    and the names ``evaluate`` defines.

    ``evaluate`` holds steps run at every iterate, the one the loop stops at included: each pass
    runs ``evaluate`` then ``body`` (both see the current state) then the updates, and once the loop
    stops (converged, or ``max_iter`` passes run, or none with ``max_iter = 0``) ``evaluate`` runs once
    more at the final state, after the ``fail_status`` check. Its names stay visible after the loop
    with their values at that iterate, so a declaration does not repeat the loop's steps after it to
    get them (the loop's code is emitted once). Its guards fail the kernel as anywhere else.

    ``carry`` holds variables updated every pass but outside the convergence test, each as
    ``(variable, initial value, update)``: the derivatives a Jacobian kernel carries through the
    iteration (:mod:`.tangent`). They are visible after the loop like the state.

    ``arrays`` holds node arrays in the state (:class:`Nodes`), each as ``(array, initial array,
    update array, scale)`` (names; the update array written by the loop's steps), over the first
    ``nodes`` entries; ``array_carry`` the same outside the convergence test (their tangents).

    ``per_direction``: how a Jacobian carries the loop's tangents (:mod:`.tangent`): ``None`` by
    the loop's size (``tangent.LOOPED_SIZE``), ``False`` a variable per tangent and direction (for
    a loop that mostly runs no pass, where the direction array costs more than it saves).
    """

    state: tuple[tuple[sp.Symbol, sp.Basic], ...]
    body: tuple[Step, ...]
    update: tuple[sp.Basic, ...]
    max_iter: sp.Basic
    tol: sp.Basic
    scales: tuple[sp.Basic, ...]
    count: sp.Symbol
    fail_status: str | None = "NOT_CONVERGED"
    comment: str = ""
    carry: tuple[tuple[sp.Symbol, sp.Basic, sp.Basic], ...] = ()
    evaluate: tuple[Step, ...] = ()
    arrays: tuple[tuple[str, str, str, sp.Basic], ...] = ()
    nodes: sp.Basic = sp.S.Zero
    array_carry: tuple[tuple[str, str, str], ...] = ()
    per_direction: bool | None = None

    def __post_init__(self):
        if not len(self.update) == len(self.scales) == len(self.state):
            raise ValueError("Iterate: one update expression and one scale per state variable")
        if (self.arrays or self.array_carry) and self.nodes == 0:
            raise ValueError("Iterate: node arrays in the state need the node count (nodes)")
        if self.fail_status is not None and self.fail_status not in STATUS:
            raise ValueError(f"unknown status {self.fail_status!r}")


@dataclass(frozen=True)
class Switch:
    """Branch on an integer-coded option: ``cases`` maps each code to the steps of its branch."""

    selector: sp.Symbol
    cases: tuple[tuple[int, tuple[Step, ...]], ...]
    comment: str = ""


@dataclass(frozen=True)
class Store:
    """Tangents into the kernel's direction array ``_T`` (derive/tangent.py): ``_T[row, j] =
    values[j]`` for every direction ``j``."""

    row: int
    values: tuple[sp.Basic, ...]


@dataclass(frozen=True)
class Load:
    """Tangents out of the kernel's direction array: ``names[j] = _T[row, j]`` for every direction."""

    row: int
    names: tuple[sp.Symbol, ...]


@dataclass(frozen=True)
class Directions:
    """Steps run once per direction ``j`` of a derivative kernel (its tangent code inside a loop,
    written once instead of once per direction): each read binds a name to ``_T[row, j]``, the
    stages (and switches of stages) compute, each write stores an expression in ``_T[row, j]``.
    Names defined inside are not visible after."""

    n: int
    reads: tuple[tuple[sp.Symbol, int], ...]
    steps: tuple[Stage | Switch, ...]
    writes: tuple[tuple[sp.Basic, int], ...]
    comment: str = ""


#: The most nodes of a node loop (:class:`Nodes`): every node array has this many entries (on the
#: kernel's stack), a node count is at most this.
MAX_NODES = 12


@dataclass(frozen=True)
class Lookup:
    """Tables chosen by an option's code: binds each ``name`` to the table of the code ``selector``
    has (a number, or a node array: a vector of one value per node, or a node x node matrix). The
    tables are constants of the generated module (padded to :data:`MAX_NODES`); a table of an
    unknown code is INVALID_INPUT. Derivatives: constants."""

    selector: sp.Basic
    tables: tuple[tuple[str, tuple[tuple[int, object], ...]], ...]
    comment: str = ""


@dataclass(frozen=True)
class Nodes:
    """Steps run once per node ``j = 0 .. count - 1`` (``count`` at most :data:`MAX_NODES`):
    ``reads`` bind names to element j of node arrays (an earlier step's, an iteration's state, a
    :class:`Lookup` vector); ``sums`` bind names to ``sum_k matrix[j, k] array[k]`` (a Lookup
    matrix, a node array); the stages compute (scalars of the node: visible only inside); each
    ``write`` defines element j of a node array (a new one, visible after). The arrays are the
    nodes' data of a collocation (Gauss-Legendre nodes and weights as data, not code per count)."""

    count: sp.Basic
    reads: tuple[tuple[sp.Symbol, str], ...]
    sums: tuple[tuple[sp.Symbol, str, str], ...]
    steps: tuple[Stage, ...]
    writes: tuple[tuple[sp.Basic, str], ...]
    comment: str = ""


@dataclass(frozen=True)
class Reduce:
    """``name = sum_k weights[k] array[k]`` over the first ``count`` nodes (``weights`` a Lookup
    vector, or None for weights 1)."""

    name: sp.Symbol
    weights: str | None
    array: str
    count: sp.Basic
    comment: str = ""


Step = Stage | Call | Iterate | Switch | Store | Load | Directions | Lookup | Nodes | Reduce


#: The most arguments a generated function takes one by one, and the most values its result tuple
#: holds (the status included). A kernel with more takes them in one array, or writes its outputs
#: into an array its caller gives (derive/lower.py); a role kernel takes layouts (:class:`Layout`).
MAX_SCALARS = 16


@dataclass(frozen=True)
class Layout:
    """A role kernel's calling convention, ``kernel(x, p, out) -> status`` (and its batch form
    ``kernel_rows(X, p, OUT, STATUS)``, one row of ``X``, ``OUT`` and ``STATUS`` per call), every
    array float64 (``STATUS`` int64):

    - ``x`` names the role's inputs in the order of the vector ``x`` (an apex, a touchdown state);
    - ``p`` names the fields of the parameter record ``p``, the vector of the map's parameters and
      options (the same record for every role of a map): the arguments not in ``x`` are read
      from it by name;
    - ``out`` receives the outputs in order (a Jacobian's values, then d output / d input
      row-major); NaN everywhere unless the returned status is OK.

    The generated index publishes each role's names, so the runtime reads and writes by name."""

    x: tuple[str, ...]
    p: tuple[str, ...]

    def __post_init__(self):
        for names, what in ((self.x, "x"), (self.p, "p")):
            if len(set(names)) != len(names):
                raise ValueError(f"layout {what} names a field twice: {names}")


@dataclass(frozen=True)
class Kernel:
    """One generated function: of scalar arguments (internal), or a role kernel of a :class:`Layout`
    (with its batch form) when ``layout`` is set."""

    name: str
    summary: str
    equations: tuple[str, ...]
    args: tuple[Arg, ...]
    steps: tuple[Step, ...]
    outputs: Group
    status: bool = True
    layout: Layout | None = None
    notes: str = ""
    module: str = ""
    check_inputs: bool = True
    #: Every public kernel ends with an all-outputs-finite guard; an internal helper whose callers
    #: check their own outputs may skip it (``check_outputs=False``).
    check_outputs: bool = True
    #: Inline into every caller at numba's IR level (``njit(inline="always")``): a map's stance kernel
    #: when its MapSpec opts in (``MapSpec.inline``), so its batch loop runs straight-line code; the
    #: iterative maps' zeroth iterates (and, an internal kernel, its derivatives: derive/tangent.py).
    inline: bool = False
    #: A role kernel inlined at numba's IR level into its own batch form only (``support.into_rows``):
    #: the kernels of a map whose MapSpec opts in (``MapSpec.inline``) and their Jacobians.
    inline_rows: bool = False
    #: Arguments and outputs the finiteness checks leave out: a derivative kernel's directions and
    #: derivatives (a non-finite derivative is NUMERICAL_RANGE for the public API, runtime/api/jacobian.py,
    #: when the Jacobian returns it; one of an output nothing uses must not fail a caller).
    unchecked: tuple[str, ...] = ()
    #: The docstring's account of the arguments, when one line per argument says less (an outlined
    #: kernel's are the caller's variables of the same names).
    doc_args: str = ""
    #: The docstring's Returns list, (name, doc) pairs, when one line per output says less (a
    #: Jacobian's derivative block in one entry).
    doc_returns: tuple[tuple[str, str], ...] = ()
    #: A kernel of one of the generator's support modules (no steps; ``module`` is that module, e.g.
    #: ``exact_stance``, rendered from derive/templates/ by derive/generate.py): a numba function of
    #: the declared arguments in their order, of the calling convention derive/lower.py's ``abi``
    #: gives its arguments and outputs. The exact simulator's stance is one.
    external: bool = False
    #: An external kernel's Jacobian: an external kernel of the same arguments returning the outputs,
    #: then d output / d ``jacobian_wrt`` (``derivative_fields`` order), then the status. Generated
    #: derivatives of a caller go through it (:mod:`.tangent`).
    jacobian: Kernel | None = None
    jacobian_wrt: tuple[str, ...] = ()
    #: Its callers' derivatives read every entry of its derivative, the identically zero ones too
    #: (:mod:`.tangent`): one of several interchangeable kernels (the zeroth iterates of the
    #: iterative maps, one per choice), whose callers are then the same code but for the callee
    #: (:mod:`.share`).
    dense_tangent: bool = False
    #: Its node loops run to the largest node count of the :class:`Lookup` that binds their count
    #: and stop at the count (a trip count LLVM knows: it unrolls them and keeps the node arrays in
    #: registers: the iterative map's apex return at 4 nodes ran in 0.93x the time of a loop to the
    #: count). Derivative kernels loop to the count (:mod:`.tangent`): their node arrays, one per
    #: direction, unrolled ran in 1.08x the time (batches of 2,000 states, interleaved runs).
    unroll_nodes: bool = True

    def __post_init__(self):
        if self.external and (self.steps or "." in self.module):
            raise ValueError(
                f"external kernel {self.name}: no steps, and module a support module of generated/"
            )
        unknown = [w for w in self.jacobian_wrt if w not in self.arg_names]
        if unknown:
            raise ValueError(f"kernel {self.name}: jacobian_wrt names unknown argument(s) {unknown}")
        if self.layout is not None:
            missing = [a for a in self.arg_names if a not in self.layout.x and a not in self.layout.p]
            stray = [a for a in self.layout.x if a not in self.arg_names]
            if missing or stray:
                raise ValueError(
                    f"kernel {self.name}: layout x {self.layout.x} and p {self.layout.p} must hold its "
                    f"arguments (missing {missing}) and x only arguments (not {stray})"
                )

    @property
    def arg_names(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.args)

    @property
    def output_names(self) -> tuple[str, ...]:
        return self.outputs.names()

    def signature(self, **extra) -> dict:
        """This role kernel's calling convention, as the generated index publishes it: its module and
        name, the names of ``x``, ``p`` and ``out`` (:class:`Layout`), plus ``extra``."""
        if self.layout is None:
            raise ValueError(f"kernel {self.name} has no layout: it is not a role kernel")
        return {
            "module": self.module,
            "name": self.name,
            "x": list(self.layout.x),
            "p": list(self.layout.p),
            "out": list(self.output_names),
            **extra,
        }


def calls(steps):
    """Every :class:`Call` in ``steps``, at any depth: in a loop's evaluation and body and in every
    branch of a switch (callers first, in order)."""
    for step in steps:
        if isinstance(step, Call):
            yield step
        elif isinstance(step, Iterate):
            yield from calls(step.evaluate)
            yield from calls(step.body)
        elif isinstance(step, Switch):
            for _, branch in step.cases:
                yield from calls(branch)


@dataclass(frozen=True)
class Module:
    """One generated file: its kernels (callees in other modules are imported automatically)."""

    name: str
    doc: str
    source: str
    kernels: Callable[[], tuple[Kernel, ...]]
