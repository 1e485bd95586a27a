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

What a map shares with a half map (options, the build's inputs, the common index fields) is their
base :class:`~.declaration.Declaration`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy as sp

from . import catalog
from .declaration import Declaration, Inputs, Option
from .ir import STATUS, Arg, Call, Group, Kernel, Layout, Module, Stage, Step, sym
from .specialize import module_kernels
from .tangent import Differentiator

__all__ = ["MapBuild", "MapInputs", "MapSpec", "Option"]

#: The build's inputs of a whole stance (the start state is the touchdown state).
MapInputs = Inputs


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


@dataclass(frozen=True, kw_only=True)
class MapSpec(Declaration):
    """One whole-stance map, declared once (``build`` gives a :class:`MapBuild`)."""

    build: Callable[[MapInputs], MapBuild]
    requires: tuple[str, ...] = ()
    notes: str = ""
    #: Inline the stance kernel into its batch and apex-return kernels, and every role kernel of the
    #: map (and its Jacobians) into its own batch form (numba IR inlining): faster batches for a small
    #: body (Geyer's apex return 137 -> 130 ns a row), but every caller compiles it again (the
    #: warm-up of every map's batch forms took 137 -> 219 s; 2-3x the compile time of the gravity
    #: maps' large, iterating bodies), so a map opts in.
    inline: bool = False
    #: Statuses the approximation itself returns on gaits the exact stance completes (for example
    #: IMAGINARY_MOMENTUM where an iterate's H^{-1} of (33) is imaginary); listed in docs/maps.md.
    approximation_statuses: tuple[str, ...] = ()
    #: The map reproduces the report's printed formulas, errors included, to measure them: it makes
    #: no accuracy claim (the tests over every map check its contract, not its accuracy).
    as_printed: bool = False
    #: The family of maps this map belongs to (None: none): maps whose kernels differ only in the
    #: kernels they call (the gravity corrections' types 0-4, in their impulse rule). A member's
    #: kernels are its own, in the family's module and with the family's options as arguments, so
    #: that every member's kernels have one layout and the same code, which derive/share.py renders
    #: once; each member is a map of its own (name, title, equations, public options and their
    #: defaults) that fixes the family's other options to the values ``fixed`` gives (by name; not
    #: the user's to choose: the index row's ``fixed``, which the runtime passes with the options).
    family: MapSpec | None = None
    fixed: tuple[tuple[str, object], ...] = ()

    def __post_init__(self):
        super().__post_init__()
        if self.family is not None:
            self._check_member()
        unknown = [s for s in self.approximation_statuses if s not in STATUS]
        if unknown:
            raise ValueError(f"map {self.name}: unknown status(es) {unknown}")
        if "k" in self.params and "constant_stiffness" not in self.requires:
            raise ValueError(
                f"map {self.name}: a map with the single stiffness k requires constant_stiffness"
            )

    def _check_member(self) -> None:
        """A member's options are the family's (same kinds and choices, in the family's order;
        defaults of its own) but for those it fixes, each to a valid value; neither has specialized
        options."""
        family = {o.name: o for o in self.family.options}
        fixed = dict(self.fixed)
        if self.family.family is not None or self.specialized() or self.family.specialized():
            raise ValueError(f"map {self.name}: a family has one level and no specialized options")
        for o in self.options:
            f = family.get(o.name)
            if f is None or (f.kind, f.values, f.low, f.high) != (o.kind, o.values, o.low, o.high):
                raise ValueError(f"map {self.name}: option {o.name} is not the family's {self.family.name}")
        order = [name for name in family if name in {o.name for o in self.options}]
        if [o.name for o in self.options] != order:
            raise ValueError(f"map {self.name}: its options are in the family's order, {order}")
        missing = set(family) - set(fixed) - {o.name for o in self.options}
        extra = set(fixed) - set(family) | set(fixed) & {o.name for o in self.options}
        if missing or extra:
            raise ValueError(
                f"map {self.name}: fixes {sorted(extra)} it may not, leaves {sorted(missing)} unset"
            )
        for name, value in self.fixed:
            self._code(family[name], value)
        if (self.params, self.requires) != (self.family.params, self.family.requires):
            raise ValueError(f"map {self.name}: parameters and requirements are the family's")

    @staticmethod
    def _code(option: Option, value) -> float:
        """The kernel argument of ``option``'s ``value``; ValueError outside its domain."""
        code = option.code(value) if option.choices else value
        if option.choices or option.domain().subs(option.symbol, code) is sp.true:
            return float(code)
        raise ValueError(f"option {option.name}: {value!r} is outside its domain")

    @property
    def module_name(self) -> str:
        """The generated module of the map's kernels: its family's (every member's kernels in one
        module, where derive/share.py renders their common body once), else its own."""
        return (self.family or self).ident

    def kernel_options(self) -> tuple[Option, ...]:
        """The options the kernels take: the family's (a member's own and those it fixes, so that
        every member's kernels have one layout and one code), else the map's."""
        return (self.family or self).options

    def fixed_codes(self) -> dict[str, float]:
        """The kernel arguments of the family's options this member fixes, by name."""
        family = {o.name: o for o in self.kernel_options()}
        return {name: self._code(family[name], value) for name, value in self.fixed}

    def kernel_name(self, role: str) -> str:
        """The generated function of ``role`` ("stance", "state_at", "apex_return")."""
        return f"{self.ident}_{role}"

    # -- arguments -----------------------------------------------------------------------------
    def stance_args(self) -> tuple[Arg, ...]:
        return catalog.TOUCHDOWN + self.param_args() + (catalog.PARAMS["q_r_lo"],) + self.option_args()

    def apex_args(self) -> tuple[Arg, ...]:
        flight = tuple(catalog.PARAMS[p] for p in ("g_f", "q_r_td", "q_r_lo"))
        return catalog.APEX_ARGS + self.param_args() + flight + self.option_args()

    def layout(self, x: tuple[Arg, ...]) -> Layout:
        """A role kernel's layout: the inputs ``x``, the map's parameter record (its parameters,
        the flights' g_f, q_r_td and q_r_lo, its kernel options)."""
        return Layout(tuple(a.name for a in x), self.p_layout(("g_f", "q_r_td", "q_r_lo")))

    # -- kernels -------------------------------------------------------------------------------
    def domain_steps(self) -> tuple[Step, ...]:
        """Checks of option choices that depend on the touchdown state (before the map's own steps)."""
        guards = tuple(g for g in (o.domain_guard() for o in self.kernel_options()) if g is not None)
        return (Stage((), guards),) if guards else ()

    def built(self) -> MapBuild:
        if "build" not in self._cache:
            self._cache["build"] = self.build(self.inputs(catalog.TOUCHDOWN, self.params + ("q_r_lo",)))
        return self._cache["build"]

    def stance_kernel(self, choice: dict | None = None) -> Kernel:
        """The stance kernel of ``choice`` of the specialized options (default: the defaults')."""
        return self.specialize(self._stance_kernel(), self._choice(choice))

    def _choice(self, choice: dict | None) -> dict:
        return self.choices()[0] if choice is None else choice

    def _stance_kernel(self) -> Kernel:
        if "stance" in self._cache:
            return self._cache["stance"]
        self._cache["stance"] = Kernel(
            name=self.kernel_name("stance"),
            summary=f"{self.title}: touchdown state -> bottom and liftoff states.",
            equations=self.equations,
            args=self.stance_args(),
            steps=self.domain_steps() + self.built().steps,
            outputs=catalog.STANCE + Group("", self.extras),
            layout=self.layout(catalog.TOUCHDOWN),
            notes=self.notes,
            module=self.module_name,
            inline=self.inline,
            inline_rows=self.inline,
        )
        return self._cache["stance"]

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
            **{o.name: sp.Float(o.default_code) for o in self.options if o.kernel},
            **{name: sp.Float(code) for name, code in self.fixed_codes().items()},
        }
        return Call(self.stance_kernel(), args, bind, comment=comment or f"stance: {self.title}")

    def state_at_kernel(self, choice: dict | None = None) -> Kernel | None:
        if self.built().state_at is None:
            return None
        t = catalog.TIME
        return self.specialize(
            Kernel(
                name=self.kernel_name("state_at"),
                summary=f"{self.title}: the polar state a time t after touchdown.",
                equations=self.equations,
                args=(t,) + self.stance_args(),
                steps=self.domain_steps() + self.built().state_at(t.symbol),
                outputs=catalog.TRAJECTORY,
                layout=self.layout((t,) + catalog.TOUCHDOWN),
                module=self.module_name,
                inline_rows=self.inline,
            ),
            self._choice(choice),
        )

    def apex_return_kernel(self, flight_kernels: Mapping[str, Kernel], choice: dict | None = None) -> Kernel:
        """Apex -> touchdown (exact ballistic descent onto ground ``ground`` higher) -> this map's
        stance -> liftoff -> next apex (exact ballistic ascent), and the step's geometry. The apex
        speed is signed: the step's direction (its sign) is the one the liftoff must keep."""
        to_td, to_apex = flight_kernels["apex_to_touchdown"], flight_kernels["liftoff_to_apex"]
        stance = self._stance_kernel()
        td = ("td_q_r", "td_q_rd", "td_q_th", "td_q_thd")
        touchdown_names = [a.name for a in catalog.TOUCHDOWN]
        passthrough = {a.name: a.symbol for a in stance.args if a.name not in touchdown_names}
        stance_outs = {f.name: f.name for f in catalog.APEX_RETURN.fields() if f.name in stance.output_names}
        stance_outs.update({f.name: f.name for f in self.extras})
        h, v, ground = catalog.APEX_ARGS[0].symbol, catalog.APEX_ARGS[1].symbol, catalog.GROUND.symbol
        direction, next_apex_x = catalog.DIRECTION.symbol, sym("next_apex_x")
        steps = (
            Stage(((direction, sp.sign(v)),), comment="the step's direction: the sign of the apex speed"),
            Call(
                to_td,
                # every apex-return input and parameter the flight takes, by name
                {
                    a.name: a.symbol
                    for a in (*catalog.APEX_ARGS, *catalog.PARAMS.values())
                    if a.name in to_td.arg_names
                },
                {
                    **dict(zip(to_td.output_names[:4], td, strict=True)),
                    "t_flight": "t_descent",
                    "foot_x": "foot_x",
                },
                comment="apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)",
            ),
            Call(
                stance,
                {**dict(zip(touchdown_names, (sym(n) for n in td), strict=True)), **passthrough},
                stance_outs,
                comment=f"stance: {(self.family or self).title}",
            ),
            Call(
                to_apex,
                {
                    **{p: sym(f"liftoff_{p}") for p in ("q_r", "q_rd", "q_th", "q_thd")},
                    "g_f": catalog.PARAMS["g_f"].symbol,
                    "direction": direction,
                },
                {
                    "apex_b_y": "apex_height",
                    "apex_b_xd": "apex_speed",
                    "t_flight": "t_ascent",
                    "apex_b_x": next_apex_x.name,
                },
                comment="liftoff -> next apex: exact ballistic ascent",
            ),
            Stage(
                (
                    (sym("step_length"), sym("foot_x") + next_apex_x),
                    (sym("foot_y"), ground - h),
                    (sym("touchdown_q_th"), sym(td[2])),
                ),
                comment="the step: apex to the foot, the foot to the next apex",
            ),
        )
        return self.specialize(
            Kernel(
                name=self.kernel_name("apex_return"),
                summary=f"Apex-return map: exact flights, stance by {self.title}.",
                equations=self.equations,
                args=self.apex_args(),
                steps=steps,
                outputs=catalog.APEX_RETURN + Group("", self.extras),
                layout=self.layout(catalog.APEX_ARGS),
                module=self.module_name,
                inline_rows=self.inline,
            ),
            self._choice(choice),
        )

    # -- derivatives ---------------------------------------------------------------------------
    def stiffness(self) -> tuple[str, ...]:
        """The map's stiffness parameters (``k``, or ``k_c`` and ``k_d``), in argument order."""
        return tuple(a.name for a in self.param_args() if a.name in ("k", "k_c", "k_d"))

    def differentiated(self) -> tuple[str, ...]:
        """The parameters the Jacobians have columns for: the stiffness, and the leg damping ``c``
        when the map takes it."""
        return self.stiffness() + tuple(p for p in ("c",) if p in self.params)

    def stance_wrt(self) -> tuple[str, ...]:
        """What the stance Jacobian differentiates with respect to: the touchdown state, the stiffness
        (and the damping, :meth:`differentiated`)."""
        return tuple(a.name for a in catalog.TOUCHDOWN) + self.differentiated()

    def apex_wrt(self) -> tuple[str, ...]:
        """What the apex-return Jacobian differentiates with respect to: apex height and speed,
        touchdown angle, ground, the stiffness (and the damping, :meth:`differentiated`)."""
        return tuple(a.name for a in catalog.APEX_ARGS) + self.differentiated()

    def jacobian_kernels(self, diff: Differentiator, flight_kernels: Mapping[str, Kernel]) -> None:
        """Declare ``<ident>_stance_jacobian`` and ``<ident>_apex_return_jacobian`` (role kernels of
        their primals' layouts),
        built by forward-mode differentiation (:mod:`.tangent`, ``diff.build()``) into module
        ``<ident>_jacobian``; the kernels they call land in ``diff.kernels`` too. The stance one is
        built first, so that the apex-return kernel's call of the stance reuses it (a superset of the
        arguments active there: the touchdown leg length is not)."""
        for choice in self.choices():
            suffix = self._suffix(choice)
            diff.jacobian(
                self.stance_kernel(choice),
                self.stance_wrt(),
                name=self.kernel_name("stance_jacobian") + suffix,
                summary=f"{self.title}: stance outputs and their derivatives with respect to the "
                "touchdown state and the stiffness.",
            )
            diff.jacobian(
                self.apex_return_kernel(flight_kernels, choice),
                self.apex_wrt(),
                name=self.kernel_name("apex_return_jacobian") + suffix,
                summary=f"Apex-return map by {self.title}, and its derivatives with respect to the apex, "
                "the touchdown angle and the stiffness.",
            )

    @staticmethod
    def _suffix(choice: dict) -> str:
        from .specialize import choice_suffix

        return choice_suffix(choice)

    def kernels(self, flight_kernels: Mapping[str, Kernel]) -> tuple[Kernel, ...]:
        """Per choice of the specialized options: the stance, state-at-time and apex-return kernels;
        before them the kernels of this module they call, and the helpers."""
        main: list[Kernel] = []
        for choice in self.choices():
            state_at = self.state_at_kernel(choice)
            main += [self.stance_kernel(choice), *((state_at,) if state_at else ())]
            main.append(self.apex_return_kernel(flight_kernels, choice))
        return module_kernels(self.module_name, self.built().helpers, main, self.labels())

    @staticmethod
    def modules(specs, flight_kernels: Mapping[str, Kernel]) -> tuple[Module, ...]:
        """The kernel modules of ``specs``: a map's own (:meth:`module`), or a family's, which holds
        every member's kernels (in the members' order; derive/share.py renders what they share
        once)."""
        groups: dict[str, list[MapSpec]] = {}
        for spec in specs:
            groups.setdefault(spec.module_name, []).append(spec)
        out = []
        for name, members in groups.items():
            family = members[0].family
            if family is None:
                out.append(members[0].module(flight_kernels))
                continue

            def kernels(members=tuple(members)) -> tuple[Kernel, ...]:
                merged: dict[str, Kernel] = {}
                for member in members:
                    for k in member.kernels(flight_kernels):
                        merged.setdefault(k.name, k)
                return tuple(merged.values())

            out.append(
                Module(
                    name=name,
                    doc=f"{family.title} (report sections {family.section}): the stance, state-at-time and "
                    f"apex-return kernels of the maps {', '.join(m.name for m in members)} (one body, "
                    "derive/share.py).",
                    source=family.source,
                    kernels=kernels,
                )
            )
        return tuple(out)

    def module(self, flight_kernels: Mapping[str, Kernel]) -> Module:
        return Module(
            name=self.ident,
            doc=f"{self.title} (report section {self.section}): stance, state-at-time and apex-return "
            "kernels.",
            source=self.source,
            kernels=lambda: self.kernels(flight_kernels),
        )

    # -- index ---------------------------------------------------------------------------------
    def index_row(self, flight_kernels: Mapping[str, Kernel]) -> dict:
        """The map's row of the generated index: what ``slipmaps maps`` lists, and every kernel's
        calling convention by role (:meth:`~.ir.Kernel.signature`), which the runtime fills by name.
        A family member's row also says which of the family's options it ``fixed``."""
        stance, state_at = self._stance_kernel(), self.state_at_kernel({})
        apex = self.apex_return_kernel(flight_kernels, {})
        jac_module = f"{self.module_name}_jacobian"
        kernels = {"stance": self.signature(stance), "apex_return": self.signature(apex)}
        if state_at is not None:
            kernels["state_at"] = self.signature(state_at)
        for role, primal, wrt in (
            ("stance", stance, self.stance_wrt()),
            ("apex_return", apex, self.apex_wrt()),
        ):
            sig = self.signature(primal)
            kernels[f"{role}_jacobian"] = {
                **sig,
                "wrt": list(wrt),
                "module": jac_module,
                "name": sig["name"].replace(primal.name, self.kernel_name(f"{role}_jacobian"), 1),
                **({"base": self.kernel_name(f"{role}_jacobian")} if "base" in sig else {}),
            }
        return {
            **self.row(
                requires=list(self.requires),
                as_printed=self.as_printed,
                approximation_statuses=list(self.approximation_statuses),
                kernels=kernels,
                fixed=self.fixed_codes(),
            ),
            "module": self.module_name,
        }
