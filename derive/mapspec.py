"""A map, declared once: :class:`MapSpec` -> its kernels and its row of the generated index.

A map module (``derive/maps/<name>.py``) derives its formulas and declares ``MAPS``: one
:class:`MapSpec` per map (name, title, report section, equations, parameters, requirements,
options, extra outputs, and a ``build`` function that returns the steps computing the stance
outputs). From the declaration follow, with no second list anywhere:

- ``<ident>_stance``: polar touchdown state -> :data:`~.catalog.STANCE` outputs (+ extras), with a
  parallel batch form (touchdown rows, scalar parameters and options);
- ``<ident>_state_at``: the polar state a time ``t`` after touchdown (batch over ``t``), where the
  map has a trajectory;
- ``<ident>_apex_return``: apex -> touchdown (exact flight) -> stance -> liftoff -> next apex
  (exact flight), three :class:`~.ir.Call` s passing values by name, with a batch form;
- the map's row of ``generated/maps_index.py`` (which the runtime API, the CLI choices, the
  tests over every map, the benchmark rows and the README map table all read).

Options are kernel arguments (float64): a choice is passed as the index of its value, an integer
option as a whole number; each gets a domain check (INVALID_INPUT outside it).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import sympy as sp

from . import catalog
from .ir import STATUS, Arg, Batch, Call, Field, Group, Guard, Kernel, Module, Stage, Step, real, sym
from .tangent import Differentiator


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

    def __post_init__(self):
        if self.choices and self.default not in self.values:
            raise ValueError(f"option {self.name}: default {self.default!r} is not one of {self.values}")
        unknown = set(self.at_rest_length) - set(self.values)
        if unknown:
            raise ValueError(f"option {self.name}: at_rest_length names unknown choices {sorted(unknown)}")

    @property
    def symbol(self) -> sp.Symbol:
        return sym(self.name)

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
class MapInputs:
    """The symbols a declaration's ``build`` works with: touchdown state, parameters, options."""

    touchdown: tuple[sp.Symbol, sp.Symbol, sp.Symbol, sp.Symbol]
    params: Mapping[str, sp.Symbol]
    options: Mapping[str, Option]

    def opt(self, name: str) -> sp.Symbol:
        return self.options[name].symbol


@dataclass(frozen=True)
class MapBuild:
    """What a declaration computes.

    ``steps`` define every :data:`~.catalog.STANCE` output and every extra, by name.
    ``state_at`` (optional) takes the time symbol ``t`` and returns steps defining ``q_r, q_rd,
    q_th, q_thd`` at ``t`` after touchdown. ``helpers`` are internal kernels placed in the map's
    module (other maps may call them).
    """

    steps: tuple[Step, ...]
    state_at: Callable[[sp.Symbol], tuple[Step, ...]] | None = None
    helpers: tuple[Kernel, ...] = ()


@dataclass(frozen=True)
class MapSpec:
    """One approximate stance map, declared once."""

    name: str  # user-facing name, e.g. "geyer", "gravity-type2"
    title: str
    section: str  # report subsection, e.g. "3.1", "4.3"
    equations: tuple[str, ...]
    params: tuple[str, ...]  # names in catalog.PARAMS, e.g. ("m", "l0", "k", "g_s")
    build: Callable[[MapInputs], MapBuild]
    requires: tuple[str, ...] = ()
    options: tuple[Option, ...] = ()
    extras: tuple[Field, ...] = ()
    summary: str = ""
    notes: str = ""
    #: Inline the stance kernel into its batch and apex-return kernels (numba IR inlining): 10-25 %
    #: faster batches for a small body, but every caller compiles it again (measured: 2-3x the
    #: compile time of the gravity maps' large, iterating bodies), so a map opts in.
    inline: bool = False
    #: Statuses the approximation itself returns on gaits the exact stance completes (for example
    #: IMAGINARY_MOMENTUM where an iterate's H^{-1} of (33) is imaginary); listed in docs/maps.md.
    approximation_statuses: tuple[str, ...] = ()
    #: The map reproduces the report's printed formulas, errors included, to measure them: it makes
    #: no accuracy claim (the tests over every map check its contract, not its accuracy).
    as_printed: bool = False
    _cache: dict = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self):
        unknown = [p for p in self.params if p not in catalog.PARAMS]
        if unknown:
            raise ValueError(f"map {self.name}: unknown parameter(s) {unknown}")
        unknown = [s for s in self.approximation_statuses if s not in STATUS]
        if unknown:
            raise ValueError(f"map {self.name}: unknown status(es) {unknown}")
        if "k" in self.params and "constant_stiffness" not in self.requires:
            raise ValueError(
                f"map {self.name}: a map with the single stiffness k requires constant_stiffness"
            )

    @property
    def ident(self) -> str:
        """The Python identifier of the map (module and kernel name prefix)."""
        return self.name.replace("-", "_")

    def kernel_name(self, role: str) -> str:
        """The generated function of ``role`` ("stance", "state_at", "apex_return")."""
        return f"{self.ident}_{role}"

    @property
    def source(self) -> str:
        """The derivation module, named in generated headers."""
        mod = self.build.__module__.removeprefix("slipmaps.")
        return mod.replace(".", "/") + ".py"

    # -- arguments -----------------------------------------------------------------------------
    def param_args(self) -> tuple[Arg, ...]:
        return tuple(catalog.PARAMS[p] for p in self.params)

    def option_args(self) -> tuple[Arg, ...]:
        return tuple(o.arg() for o in self.options)

    def stance_args(self) -> tuple[Arg, ...]:
        return catalog.TOUCHDOWN + self.param_args() + (catalog.PARAMS["q_r_lo"],) + self.option_args()

    def apex_args(self) -> tuple[Arg, ...]:
        flight = tuple(catalog.PARAMS[p] for p in ("g_f", "q_r_td", "q_r_lo"))
        return catalog.APEX_ARGS + self.param_args() + flight + self.option_args()

    # -- kernels -------------------------------------------------------------------------------
    def domain_steps(self) -> tuple[Step, ...]:
        """Checks of option choices that depend on the touchdown state (before the map's own steps)."""
        guards = tuple(g for g in (o.domain_guard() for o in self.options) if g is not None)
        return (Stage((), guards),) if guards else ()

    def built(self) -> MapBuild:
        if "build" not in self._cache:
            inputs = MapInputs(
                touchdown=tuple(a.symbol for a in catalog.TOUCHDOWN),
                params={p: catalog.PARAMS[p].symbol for p in self.params + ("q_r_lo",)},
                options={o.name: o for o in self.options},
            )
            self._cache["build"] = self.build(inputs)
        return self._cache["build"]

    def stance_kernel(self) -> Kernel:
        return Kernel(
            name=self.kernel_name("stance"),
            summary=f"{self.title}: touchdown state -> bottom and liftoff states.",
            equations=self.equations,
            args=self.stance_args(),
            steps=self.domain_steps() + self.built().steps,
            outputs=catalog.STANCE + Group("", self.extras),
            batch=Batch(tuple(a.name for a in catalog.TOUCHDOWN)),
            notes=self.notes,
            module=self.ident,
            inline=self.inline,
        )

    def stance_call(
        self,
        touchdown: tuple[sp.Basic, ...],
        params: Mapping[str, sp.Basic],
        bind: Mapping[str, str],
        comment: str = "",
    ) -> Call:
        """A :class:`~.ir.Call` of this map's stance kernel at its default options, for another
        map's steps. ``params`` gives an expression for every parameter of the map and q_r_lo."""
        missing = [p for p in self.params + ("q_r_lo",) if p not in params]
        if missing:
            raise ValueError(f"map {self.name}: stance_call needs parameter(s) {missing}")
        args = {
            **{a.name: x for a, x in zip(catalog.TOUCHDOWN, touchdown, strict=True)},
            **{p: params[p] for p in self.params + ("q_r_lo",)},
            **{o.name: sp.Float(o.default_code) for o in self.options},
        }
        return Call(self.stance_kernel(), args, bind, comment=comment or f"stance: {self.title}")

    def state_at_kernel(self) -> Kernel | None:
        if self.built().state_at is None:
            return None
        t = catalog.TIME
        return Kernel(
            name=self.kernel_name("state_at"),
            summary=f"{self.title}: the polar state a time t after touchdown.",
            equations=self.equations,
            args=(t,) + self.stance_args(),
            steps=self.domain_steps() + self.built().state_at(t.symbol),
            outputs=catalog.TRAJECTORY,
            batch=Batch((t.name,)),
            module=self.ident,
        )

    def apex_return_kernel(self, flight_kernels: Mapping[str, Kernel]) -> Kernel:
        to_td, to_apex = flight_kernels["apex_to_touchdown"], flight_kernels["liftoff_to_apex"]
        stance = self.stance_kernel()
        td = ("td_q_r", "td_q_rd", "td_q_th", "td_q_thd")
        touchdown_names = [a.name for a in catalog.TOUCHDOWN]
        passthrough = {a.name: a.symbol for a in stance.args if a.name not in touchdown_names}
        stance_outs = {f.name: f.name for f in catalog.APEX_RETURN.fields() if f.name in stance.output_names}
        stance_outs.update({f.name: f.name for f in self.extras})
        steps = (
            Call(
                to_td,
                {
                    "b_y_apex": catalog.APEX_ARGS[0].symbol,
                    "b_xd_apex": catalog.APEX_ARGS[1].symbol,
                    "q_th_td": catalog.TOUCHDOWN[2].symbol,
                    "q_r_td": catalog.PARAMS["q_r_td"].symbol,
                    "g_f": catalog.PARAMS["g_f"].symbol,
                },
                {**dict(zip(to_td.output_names[:4], td, strict=True)), "t_flight": "t_descent"},
                comment="apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)",
            ),
            Call(
                stance,
                {**dict(zip(touchdown_names, (sym(n) for n in td), strict=True)), **passthrough},
                stance_outs,
                comment=f"stance: {self.title}",
            ),
            Call(
                to_apex,
                {
                    **{p: sym(f"liftoff_{p}") for p in ("q_r", "q_rd", "q_th", "q_thd")},
                    "g_f": catalog.PARAMS["g_f"].symbol,
                },
                {"apex_b_y": "apex_height", "apex_b_xd": "apex_speed", "t_flight": "t_ascent"},
                comment="liftoff -> next apex: exact ballistic ascent",
            ),
        )
        return Kernel(
            name=self.kernel_name("apex_return"),
            summary=f"Apex-return map: exact flights, stance by {self.title}.",
            equations=self.equations,
            args=self.apex_args(),
            steps=steps,
            outputs=catalog.APEX_RETURN + Group("", self.extras),
            batch=Batch(tuple(a.name for a in catalog.APEX_ARGS)),
            module=self.ident,
        )

    # -- derivatives ---------------------------------------------------------------------------
    def stiffness(self) -> tuple[str, ...]:
        """The map's stiffness parameters (``k``, or ``k_c`` and ``k_d``), in argument order."""
        return tuple(a.name for a in self.param_args() if a.name in ("k", "k_c", "k_d"))

    def stance_wrt(self) -> tuple[str, ...]:
        """What the stance Jacobian differentiates with respect to: the touchdown state, the stiffness."""
        return tuple(a.name for a in catalog.TOUCHDOWN) + self.stiffness()

    def apex_wrt(self) -> tuple[str, ...]:
        """What the apex-return Jacobian differentiates with respect to: apex height and speed,
        touchdown angle, the stiffness."""
        return tuple(a.name for a in catalog.APEX_ARGS) + self.stiffness()

    def jacobian_kernels(self, diff: Differentiator, flight_kernels: Mapping[str, Kernel]) -> None:
        """Declare ``<ident>_stance_jacobian`` and ``<ident>_apex_return_jacobian`` (with batch forms),
        built by forward-mode differentiation (:mod:`.tangent`, ``diff.build()``) into module
        ``<ident>_jacobian``; the kernels they call land in ``diff.kernels`` too. The stance one is
        built first, so that the apex-return kernel's call of the stance reuses it (a superset of the
        arguments active there: the touchdown leg length is not)."""
        diff.jacobian(
            self.stance_kernel(),
            self.stance_wrt(),
            name=self.kernel_name("stance_jacobian"),
            summary=f"{self.title}: stance outputs and their derivatives with respect to the touchdown "
            "state and the stiffness.",
            batch=Batch(tuple(a.name for a in catalog.TOUCHDOWN)),
        )
        diff.jacobian(
            self.apex_return_kernel(flight_kernels),
            self.apex_wrt(),
            name=self.kernel_name("apex_return_jacobian"),
            summary=f"Apex-return map by {self.title}, and its derivatives with respect to the apex, "
            "the touchdown angle and the stiffness.",
            batch=Batch(tuple(a.name for a in catalog.APEX_ARGS)),
        )

    def kernels(self, flight_kernels: Mapping[str, Kernel]) -> tuple[Kernel, ...]:
        state_at = self.state_at_kernel()
        main = (self.stance_kernel(),) + ((state_at,) if state_at else ())
        return self.built().helpers + main + (self.apex_return_kernel(flight_kernels),)

    def module(self, flight_kernels: Mapping[str, Kernel]) -> Module:
        return Module(
            name=self.ident,
            doc=f"{self.title} (report section {self.section}): stance, state-at-time and apex-return "
            "kernels.",
            source=self.source,
            kernels=lambda: self.kernels(flight_kernels),
        )

    # -- index ---------------------------------------------------------------------------------
    def index_row(self) -> dict:
        stance, state_at = self.stance_kernel(), self.state_at_kernel()
        return {
            "name": self.name,
            "title": self.title,
            "section": self.section,
            "equations": list(self.equations),
            "requires": list(self.requires),
            "params": list(self.params),
            "options": [o.index_row() for o in self.options],
            "module": self.ident,
            "summary": self.summary,
            "as_printed": self.as_printed,
            "approximation_statuses": list(self.approximation_statuses),
            "kernels": {
                "stance": stance.name,
                "state_at": state_at.name if state_at else None,
                "apex_return": self.kernel_name("apex_return"),
            },
            "jacobian": {
                "module": f"{self.ident}_jacobian",
                "stance": self.kernel_name("stance_jacobian"),
                "apex_return": self.kernel_name("apex_return_jacobian"),
                "stance_wrt": list(self.stance_wrt()),
                "apex_wrt": list(self.apex_wrt()),
            },
            "stance_args": list(stance.arg_names),
            "apex_args": [a.name for a in self.apex_args()],
            "extras": [{"name": f.name, "doc": f.doc, "unit": f.unit} for f in self.extras],
        }
