"""What every declaration shares: :class:`Option`, :class:`Inputs` and the base :class:`Declaration`.

A whole-stance map (:class:`~.mapspec.MapSpec`) and a half-stance map (:class:`~.halfspec.HalfSpec`)
are both a :class:`Declaration`: a name, title, report section and equations, the parameters (names
in :data:`~.catalog.PARAMS`), the options, the extra outputs, the roles the studies read, and a
``build`` function given the symbols of an :class:`Inputs`. The base holds what follows from those
once: the identifier, the source named in generated headers, the parameter and option arguments,
the build's inputs and the index row's common fields. The subclasses add what they are: the
kernels of a whole stance (stance, state-at-time, apex return, Jacobians) or of one half.

Options are kernel arguments (float64): a choice is passed as the index of its value, an integer
option as a whole number; each gets a domain check (INVALID_INPUT outside it). An option whose
choices name ``backends`` selects the implementation instead and is not a kernel argument. A choice
option declared ``specialize`` is not a kernel argument either: each of its choices gets kernels of
its own (:mod:`.specialize`), and the runtime calls the kernel of the choice.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import sympy as sp

from . import catalog
from .ir import Arg, Field, Guard, real, sym

__all__ = ["Declaration", "Inputs", "Option"]


@dataclass(frozen=True)
class Option:
    """A map option: a choice among named values, an integer or a float, with its default."""

    name: str
    doc: str
    default: float | int | str
    choices: tuple[tuple[str, str], ...] = ()  # (value, what it means); passed as its index
    low: float | None = None
    high: float | None = None
    integer: bool = False
    #: Choices that assume touchdown at the rest length (q_r_td = l0): with another touchdown leg
    #: length the kernels return INVALID_INPUT.
    at_rest_length: tuple[str, ...] = ()
    #: Choices that run the map by another implementation than its generated kernels: (choice, the
    #: Python module whose ``BACKEND`` runs it), e.g. the exact map's ``method="scipy"`` (solve_ivp).
    #: Such an option selects the implementation and is not a kernel argument.
    backends: tuple[tuple[str, str], ...] = ()
    #: What the studies do with the option (which of its values they measure): any of
    #: :data:`slipmaps.derive.maps.OPTION_ROLES`; published in the index (``Option.roles``).
    roles: tuple[str, ...] = ()
    #: Each choice gets kernels of its own (named ``<kernel>_<option>_<choice>``) and the option is not
    #: a kernel argument (:mod:`.specialize`): for an option whose choices select different callees,
    #: so that the first call of one choice compiles only that choice's callees.
    specialize: bool = False

    def __post_init__(self):
        if self.specialize and (not self.choices or self.backends):
            raise ValueError(f"option {self.name}: only a choice option without backends can specialize")
        if self.choices and self.default not in self.values:
            raise ValueError(f"option {self.name}: default {self.default!r} is not one of {self.values}")
        unknown = {c for c, _ in self.backends} - set(self.values)
        if unknown:
            raise ValueError(f"option {self.name}: backends name unknown choices {sorted(unknown)}")
        unknown = set(self.at_rest_length) - set(self.values)
        if unknown:
            raise ValueError(f"option {self.name}: at_rest_length names unknown choices {sorted(unknown)}")

    @property
    def symbol(self) -> sp.Symbol:
        return sym(self.name)

    @property
    def kernel(self) -> bool:
        """Whether the kernels take this option as an argument (an option choosing the
        implementation, :attr:`backends`, or one with kernels per choice, :attr:`specialize`, is not
        one)."""
        return not self.backends and not self.specialize

    @property
    def kind(self) -> str:
        return "choice" if self.choices else ("int" if self.integer else "float")

    @property
    def values(self) -> tuple[str, ...]:
        return tuple(v for v, _ in self.choices)

    def code(self, value: str) -> int:
        """The integer a kernel receives for the choice ``value``."""
        return self.values.index(value)

    def is_(self, value: str) -> sp.Basic:
        """Condition: this choice option equals ``value`` (for expressions that select by option)."""
        return sp.Eq(self.symbol, self.code(value))

    def domain(self) -> sp.Basic:
        x = real(self.symbol)
        if self.choices:
            return sp.Or(*(sp.Eq(x, i) for i in range(len(self.choices))))
        conds = []
        if self.low is not None:
            conds.append(x >= self.low)
        if self.high is not None:
            conds.append(x <= self.high)
        if self.integer:
            conds.append(sp.Eq(x, sp.floor(x)))
        return sp.And(*conds) if conds else sp.true

    def arg(self) -> Arg:
        if self.choices:
            doc = f"{self.doc}: " + ", ".join(f"{i} = {v}" for i, v in enumerate(self.values))
        else:
            rng = (
                f" in [{self.low:g}, {self.high:g}]" if self.low is not None and self.high is not None else ""
            )
            doc = f"{self.doc}{rng}"
        dom = self.domain()
        return Arg(self.symbol, f"option {self.name}: {doc}", None if dom is sp.true else dom)

    @property
    def default_code(self) -> float | int:
        """The value a kernel receives for the default (a choice's index)."""
        return self.code(self.default) if self.choices else self.default

    def index_row(self) -> dict:
        return {
            "name": self.name,
            "kind": self.kind,
            "default": self.default,
            "doc": self.doc,
            "choices": [{"value": v, "doc": d} for v, d in self.choices],
            "low": self.low,
            "high": self.high,
            "at_rest_length": list(self.at_rest_length),
            "kernel": self.kernel,
            "specialize": self.specialize,
            "backends": dict(self.backends),
            "roles": list(self.roles),
        }

    def domain_guard(self) -> Guard | None:
        """The run-time check of :attr:`at_rest_length` (None when no choice needs it)."""
        if not self.at_rest_length:
            return None
        q_r_td, l0 = catalog.PARAMS["q_r_td"].symbol, catalog.PARAMS["l0"].symbol
        at_rest = sp.Abs(real(q_r_td) - real(l0)) <= catalog.REST_LENGTH_TOLERANCE * real(l0)
        others = [self.is_(v) for v in self.values if v not in self.at_rest_length]
        return Guard(
            sp.Or(*others, at_rest),
            "INVALID_INPUT",
            f"{self.name} {'/'.join(self.at_rest_length)} need q_r_td = l0",
        )


@dataclass(frozen=True)
class Inputs:
    """The symbols a declaration's ``build`` works with: the start state (a whole stance's, or a
    compression half's: the touchdown state; a decompression half's: the bottom state), the
    parameters and the options."""

    state: tuple[sp.Symbol, sp.Symbol, sp.Symbol, sp.Symbol]
    params: Mapping[str, sp.Symbol]
    options: Mapping[str, Option]

    @property
    def touchdown(self) -> tuple[sp.Symbol, sp.Symbol, sp.Symbol, sp.Symbol]:
        """The start state of a whole stance, by its name."""
        return self.state

    def opt(self, name: str) -> sp.Symbol:
        return self.options[name].symbol


@dataclass(frozen=True, kw_only=True)
class Declaration:
    """A map or half map, declared once (module docstring); every field by keyword."""

    name: str  # user-facing, e.g. "geyer", "gravity-type2", "iterative-compression"
    title: str
    section: str  # report subsection, e.g. "3.1", "5.2.1"
    equations: tuple[str, ...]
    params: tuple[str, ...]  # names in catalog.PARAMS
    build: Callable
    options: tuple[Option, ...] = ()
    extras: tuple[Field, ...] = ()
    summary: str = ""
    #: What the studies and the command line do with it: any of
    #: :data:`slipmaps.derive.maps.MAP_ROLES`; published in the index (``MapInfo.roles``).
    roles: tuple[str, ...] = ()
    _cache: dict = field(default_factory=dict, compare=False, repr=False)

    #: "map" or "half map", in messages.
    kind = "map"

    def __post_init__(self):
        unknown = [p for p in self.params if p not in catalog.PARAMS]
        if unknown:
            raise ValueError(f"{self.kind} {self.name}: unknown parameter(s) {unknown}")

    @property
    def ident(self) -> str:
        """The Python identifier (module and kernel name prefix)."""
        return self.name.replace("-", "_")

    @property
    def source(self) -> str:
        """The derivation module, named in generated headers."""
        mod = self.build.__module__.removeprefix("slipmaps.")
        return mod.replace(".", "/") + ".py"

    def param_args(self) -> tuple[Arg, ...]:
        return tuple(catalog.PARAMS[p] for p in self.params)

    def kernel_options(self) -> tuple[Option, ...]:
        """The options the kernels take as arguments or specialize on (a family member's are its
        family's: :attr:`~.mapspec.MapSpec.family`)."""
        return self.options

    def option_args(self) -> tuple[Arg, ...]:
        """The options' arguments of the generic kernels (the specialized options' included:
        :meth:`choices` removes them)."""
        return tuple(o.arg() for o in self.kernel_options() if o.kernel or o.specialize)

    def p_layout(self, extra: tuple[str, ...] = ()) -> tuple[str, ...]:
        """The parameter record of every role kernel of this declaration (:class:`~.ir.Layout`'s
        ``p``): its parameters and ``extra`` in the parameter table's order, then the options that
        are kernel arguments (the specialized ones too: a choice's kernels drop theirs,
        :mod:`.specialize`)."""
        names = set(self.params) | set(extra)
        return tuple(p for p in catalog.PARAM_ORDER if p in names) + tuple(a.name for a in self.option_args())

    def specialized(self) -> tuple[Option, ...]:
        """The options with kernels per choice (:attr:`Option.specialize`)."""
        return tuple(o for o in self.options if o.specialize)

    def labels(self) -> dict[str, tuple[str, ...]]:
        """Each specialized option's values by code (:func:`.specialize.specialize`)."""
        return {o.name: o.values for o in self.specialized()}

    def choices(self) -> tuple[dict[str, tuple[int, str]], ...]:
        """Every combination of the specialized options' choices (option name -> (code, value)),
        the defaults' first; one empty choice without specialized options."""
        combos: list[dict] = [{}]
        for o in self.specialized():
            order = (o.default,) + tuple(v for v in o.values if v != o.default)
            combos = [{**c, o.name: (o.code(v), v)} for c in combos for v in order]
        return tuple(combos)

    def choice_key(self, choice: dict[str, tuple[int, str]]) -> str:
        """The index's key of a choice: its values, joined by commas."""
        return ",".join(value for _, value in choice.values())

    def specialize(self, kernel, choice: dict[str, tuple[int, str]]):
        """``kernel`` (a generic kernel of this declaration) for ``choice`` (:mod:`.specialize`)."""
        from .specialize import specialize

        return specialize(kernel, choice, self.labels()) if choice else kernel

    def signature(self, kernel) -> dict:
        """A role's published convention, given its generic kernel: the default choice's
        :meth:`~.ir.Kernel.signature` and, with specialized options, the generic name (``base``): the
        kernel of a choice is ``base`` + the choice's suffix (the index row's ``choices``)."""
        chosen = self.specialize(kernel, self.choices()[0])
        if not self.specialized():
            return chosen.signature()
        return {**chosen.signature(), "base": kernel.name}

    def choice_suffixes(self) -> dict[str, str]:
        """The index row's ``choices``: each choice's key (:meth:`choice_key`) -> its kernels' name
        suffix (empty without specialized options)."""
        from .specialize import choice_suffix

        if not self.specialized():
            return {}
        return {self.choice_key(c): choice_suffix(c) for c in self.choices()}

    def inputs(self, state: tuple[Arg, ...], params: tuple[str, ...]) -> Inputs:
        """The symbols ``build`` is given: ``state``'s, the parameters ``params``' and the options."""
        return Inputs(
            state=tuple(a.symbol for a in state),
            params={p: catalog.PARAMS[p].symbol for p in params},
            options={o.name: o for o in self.kernel_options()},
        )

    def row(self, **extra) -> dict:
        """The index row's fields every declaration has, then ``extra``."""
        return {
            "name": self.name,
            "title": self.title,
            "section": self.section,
            "equations": list(self.equations),
            "params": list(self.params),
            "options": [o.index_row() for o in self.options],
            "module": self.ident,
            "summary": self.summary,
            "roles": list(self.roles),
            "specialized": [o.name for o in self.specialized()],
            "choices": self.choice_suffixes(),
            "extras": [{"name": f.name, "doc": f.doc, "unit": f.unit, "odd": f.odd} for f in self.extras],
            **extra,
        }
