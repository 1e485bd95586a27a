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
from .ir import Arg, Batch, Field, Group, Kernel, Module, Step, positive, sym
from .specialize import module_kernels

__all__ = ["HALF_OUTPUTS", "START", "HalfInputs", "HalfSpec"]

#: Where a half starts -> where it ends.
START = {"touchdown": "bottom", "bottom": "liftoff"}

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
                batch=Batch(tuple(a.name for a in state)),
                module=self.ident,
            )
        return self.specialize(self._cache["kernel"], self.choices()[0] if choice is None else choice)

    def module(self) -> Module:
        return Module(
            name=self.ident,
            doc=f"{self.title} (report section {self.section}): {self.start} -> {self.end}.",
            source=self.source,
            kernels=lambda: module_kernels(
                self.ident, (), [self.kernel(c) for c in self.choices()], self.labels()
            ),
        )

    def index_row(self) -> dict:
        return self.row(
            whole=self.whole,
            start=self.start,
            end=self.end,
            requires=[],
            kernels={"half": self.signature(self.kernel({}))},
        )
