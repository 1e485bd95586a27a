"""A finer kernel boundary by bisection (:meth:`~.viability.ViableSet.boundary`).

The kernel S_V is known at the grid's nodes. Between two neighbouring nodes (along one state axis)
of which one is in the kernel and the other is not, the boundary is located by bisection of the
predicate "some action of the grid takes this state, by one step of the map that does not fail, into
a cell all of whose nodes are in the kernel" (the conservative rule of the fixed point, now at a
state between the nodes). At the two nodes the predicate is their kernel membership (the kernel is a
fixed point of it), so every bisection keeps a bracket; all the edges are bisected together, one
batch of the map per iteration (the edges x the actions). The kernel itself is not changed: the
bracket is where the grid's kernel ends on that edge, ``iterations`` halvings finer than the grid.
Bisection finds one crossing per edge: where the predicate changes more than once between two
nodes, the bracket holds one of the crossings.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .viability_kernel import cell_viable, cells
from .viability_map import speeds_on_energy, steps

__all__ = ["Boundary", "boundary", "viable_somewhere"]


@dataclass(frozen=True)
class Boundary:
    """The refined boundary: per edge (a pair of neighbouring nodes, one in the kernel), ``axis``
    (the state axis it runs along), ``inside`` and ``outside`` (the nodes' indices, (edges, state
    dims) int arrays), ``low`` and ``high`` (the final bracket along the axis, in its unit: one end
    passes the predicate, the other does not) and ``position`` (the bracket's middle)."""

    axis: np.ndarray
    inside: np.ndarray
    outside: np.ndarray
    low: np.ndarray
    high: np.ndarray

    @property
    def position(self) -> np.ndarray:
        return 0.5 * (self.low + self.high)


def _edges(kernel: np.ndarray):
    """(axis, inside node, outside node) of every pair of neighbours that the kernel separates."""
    out = []
    for axis in range(kernel.ndim):
        a = np.take(kernel, range(kernel.shape[axis] - 1), axis=axis)
        b = np.take(kernel, range(1, kernel.shape[axis]), axis=axis)
        for idx in np.argwhere(a != b):
            lo = tuple(idx)
            hi = tuple(i + (1 if k == axis else 0) for k, i in enumerate(idx))
            inside, outside = (lo, hi) if kernel[lo] else (hi, lo)
            out.append((axis, inside, outside))
    return out


def viable_somewhere(vs, points: np.ndarray) -> np.ndarray:
    """The predicate at ``points`` (n, state dims): a step by an action of the grid that does not
    fail and whose next state's cell is viable under the kernel."""
    grids = list(vs.states.values())
    h = points[:, 0]
    v = points[:, 1] if vs.energy is None else speeds_on_energy(vs.params, vs.energy, h)
    ok = cell_viable(vs.kernel, vs.outside)
    rates = vs.actions.get("retraction_rate")
    found = np.zeros(len(points), dtype=bool)
    for p in (
        [vs.params] if "k_d" not in vs.actions else [vs.params.with_(k_d=float(k)) for k in vs.actions["k_d"]]
    ):
        bad, _, nxt = steps(
            vs.map, p, h, v, vs.actions["touchdown_angle"], rates, vs.energy, vs.ground, vs.options
        )
        viable = ok[cells(nxt, bad, grids)]
        found |= viable.reshape(len(points), -1).any(axis=1)
    return found


def boundary(vs, iterations: int = 20) -> Boundary:
    """The kernel's boundary of ``vs`` on every edge of the grid it crosses, bisected ``iterations``
    times (module docstring)."""
    edges = _edges(vs.kernel)
    grids = list(vs.states.values())
    d = len(grids)
    n = len(edges)
    axis = np.array([e[0] for e in edges], dtype=int)
    inside = np.array([e[1] for e in edges], dtype=int).reshape(n, d)
    outside = np.array([e[2] for e in edges], dtype=int).reshape(n, d)
    # the points: the inside node's coordinates, the axis' coordinate moving between the two nodes
    base = np.column_stack([g[inside[:, k]] for k, g in enumerate(grids)]) if n else np.empty((0, d))
    yes = base[np.arange(n), axis].copy() if n else np.empty(0)  # passes the predicate
    no = np.array([grids[a][outside[i, a]] for i, a in enumerate(axis)]) if n else np.empty(0)
    for _ in range(iterations if n else 0):
        mid = 0.5 * (yes + no)
        points = base.copy()
        points[np.arange(n), axis] = mid
        passed = viable_somewhere(vs, points)
        yes = np.where(passed, mid, yes)
        no = np.where(passed, no, mid)
    return Boundary(axis, inside, outside, np.minimum(yes, no), np.maximum(yes, no))
