"""A half-stance map, declared once: :class:`HalfSpec` -> its kernel and its row of the index.

The report's variable-stiffness maps split the stance at the bottom (section 5): the compression
half runs from the touchdown state to the bottom with k_c, the decompression half from the bottom
to liftoff with k_d. A controller that picks k_d at the bottom calls them one after the other. A
half map module declares ``HALVES`` beside its ``MAPS``; from the declaration follow, with no second
list anywhere:

- ``<ident>``: the start state (touchdown or bottom, polar) -> ``t_half`` and the end state
  (bottom or liftoff) + extras, with a parallel batch form over start-state rows;
- its row ``HALVES`` of ``generated/maps_index.py`` (the runtime's ``half_stance`` API, ``slipmaps
  maps`` and docs/maps.md read it).

At the bottom q_rd = 0 by definition: a decompression half reads q_r, q_th and q_thd of its start
state and ignores q_rd.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from . import catalog
from .declaration import Declaration, Inputs
from .ir import Arg, Call, Field, Group, Kernel, Layout, Module, Stage, Step, positive, sym
from .specialize import module_kernels

__all__ = ["APEX_OUTPUTS", "HALF_OUTPUTS", "START", "HalfInputs", "HalfSpec"]

#: Where a half starts -> where it ends.
START = {"touchdown": "bottom", "bottom": "liftoff"}

#: Outputs of a decompression half's ``apex`` role: the half, then the exact flight to the next apex.
APEX_OUTPUTS = Group(
    "",
    (
        Field("apex_height", "next apex height above the ground the foot stood on", "m"),
        Field("apex_speed", "next apex horizontal speed (signed)", "m/s", odd=True),
        Field("t_half", "time from the bottom to liftoff", "s"),
        Field("t_ascent", "flight time from liftoff to the next apex", "s"),
        Group("liftoff", catalog.POLAR, "state at liftoff (q_r = q_r_lo)"),
    ),
)

#: Outputs of every half map (before its extras).
HALF_OUTPUTS = Group(
    "",
    (
        Field("t_half", "time from the start state to the end state", "s"),
        Group("end", catalog.POLAR, "state at the end of the half (the bottom or liftoff)"),
    ),
)


def start_args(start: str) -> tuple[Arg, ...]:
    """The polar start state: ``q_r_td ... q_thd_td`` (touchdown) or ``q_r_b ... q_thd_b`` (bottom)."""
    if start == "touchdown":
        return catalog.TOUCHDOWN
    q_r_b, q_th_b = sym("q_r_b"), sym("q_th_b")
    domains = {0: positive(q_r_b), 2: sp.Abs(q_th_b) < sp.pi / 2}
    notes = {0: ", > 0", 1: " (not read: 0 at the bottom)", 2: ", |q_th_b| < pi/2"}
    return tuple(
        Arg(sym(f"{f.name}_b"), f"bottom {f.doc} [{f.unit}]{notes.get(i, '')}", domains.get(i))
        for i, f in enumerate(catalog.POLAR)
    )


#: The build's inputs of a half (the start state: the touchdown or the bottom state).
HalfInputs = Inputs


@dataclass(frozen=True, kw_only=True)
class HalfSpec(Declaration):
    """One half-stance map, declared once (``build`` gives the steps defining ``t_half``, ``end_q_r``
    ... ``end_q_thd`` and the extras)."""

    whole: str  # the whole-stance map it composes into
    start: str  # "touchdown" or "bottom"
    build: Callable[[HalfInputs], tuple[Step, ...]]

    kind = "half map"

    def __post_init__(self):
        if self.start not in START:
            raise ValueError(
                f"half map {self.name}: start must be one of {sorted(START)}, got {self.start!r}"
            )
        super().__post_init__()

    @property
    def end(self) -> str:
        return START[self.start]

    def args(self) -> tuple[Arg, ...]:
        return start_args(self.start) + self.param_args() + self.option_args()

    def kernel(self, choice: dict | None = None) -> Kernel:
        """The half's kernel of ``choice`` of the specialized options (default: the defaults')."""
        if "kernel" not in self._cache:
            state = start_args(self.start)
            self._cache["kernel"] = Kernel(
                name=self.ident,
                summary=f"{self.title}: {self.start} state -> {self.end} state.",
                equations=self.equations,
                args=self.args(),
                steps=self.build(self.inputs(state, self.params)),
                outputs=HALF_OUTPUTS + Group("", self.extras),
                layout=Layout(tuple(a.name for a in state), self.p_layout()),
                module=self.ident,
            )
        return self.specialize(self._cache["kernel"], self.choices()[0] if choice is None else choice)

    def apex_kernel(self, choice: dict | None = None) -> Kernel | None:
        """A decompression half's ``apex`` role (None for a compression half): the bottom state ->
        this half -> the exact ballistic ascent to the next apex, in the direction the body moves at
        liftoff (a controller's model of the rest of a step once it has measured the bottom)."""
        if self.start != "bottom":
            return None
        if "apex" not in self._cache:
            from .model.kernels import flight_kernels

            half = self.kernel({})  # the generic kernel: the specialization reaches it
            ascent = flight_kernels()["liftoff_to_apex"]
            g_f = catalog.PARAMS["g_f"]
            lo = {q: sym(f"liftoff_{q}") for q in ("q_r", "q_rd", "q_th", "q_thd")}
            b_xd = -sp.sin(lo["q_th"]) * lo["q_rd"] - lo["q_r"] * sp.cos(lo["q_th"]) * lo["q_thd"]
            direction = sym("direction")
            steps = (
                Call(
                    half,
                    {a.name: a.symbol for a in half.args},
                    {"t_half": "t_half", **{f"end_{q}": f"liftoff_{q}" for q in lo}},
                    comment=f"the half: {self.title}",
                ),
                Stage(((direction, sp.sign(b_xd)),), comment="the direction the body moves at liftoff"),
                Call(
                    ascent,
                    {**{q: lo[q] for q in lo}, "g_f": g_f.symbol, "direction": direction},
                    {"apex_b_y": "apex_height", "apex_b_xd": "apex_speed", "t_flight": "t_ascent"},
                    comment="liftoff -> next apex: exact ballistic ascent",
                ),
            )
            self._cache["apex"] = Kernel(
                name=f"{self.ident}_apex",
                summary=f"{self.title}, then the exact flight to the next apex: bottom state -> next apex.",
                equations=self.equations,
                args=half.args + (g_f,),
                steps=steps,
                outputs=APEX_OUTPUTS,
                layout=Layout(half.layout.x, self.p_layout(("g_f",))),
                module=self.ident,
            )
        return self.specialize(self._cache["apex"], self.choices()[0] if choice is None else choice)

    def module(self) -> Module:
        def kernels():
            main = [self.kernel(c) for c in self.choices()]
            main += [k for k in (self.apex_kernel(c) for c in self.choices()) if k is not None]
            return module_kernels(self.ident, (), main, self.labels())

        return Module(
            name=self.ident,
            doc=f"{self.title} (report section {self.section}): {self.start} -> {self.end}.",
            source=self.source,
            kernels=kernels,
        )

    def index_row(self) -> dict:
        return self.row(
            whole=self.whole,
            start=self.start,
            end=self.end,
            requires=[],
            kernels={
                "half": self.signature(self.kernel({})),
                **({"apex": self.signature(self.apex_kernel({}))} if self.start == "bottom" else {}),
            },
        )
