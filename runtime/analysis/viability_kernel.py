"""The viable set and the viability kernel of a transition map on a grid (Heim and Spröwitz, "Beyond
basins of attraction: quantifying robustness of natural dynamics", IEEE T-RO 2019; their code,
sheim/vibly, ``viability/viability.py``).

Discretisation, conservative: the next state of a pair falls in a cell of the state grid (per
dimension the two nodes around it, found by ``np.digitize`` as vibly does: a next state exactly on a
node belongs to the cell above it); the pair is viable only when every node of that cell is in the
current kernel estimate. A next state outside the grid is not viable (``outside="fail"``, the
default), or, as vibly does, is judged by the nodes of its cell that exist (``outside="edge"``: the
edge node(s) alone).

Iteration (vibly's ``compute_QV``): Q_V starts as the pairs that do not fail, S_V as the states with
a pair in Q_V; each round keeps the pairs whose cell is viable under S_V and projects again, until S_V
no longer changes. Every round removes pairs only, so it ends, at the largest set that is its own
image (the kernel is a fixed point: ``is_fixed_point``). The measure of a state is the share of
its actions in Q_V (vibly's ``project_Q2S(Q_V, proj_opt=np.mean)``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["OUTSIDE", "Kernel", "cells", "cell_viable", "is_fixed_point", "viable_set"]

#: How a next state beyond the grid is judged (module docstring).
OUTSIDE = ("fail", "edge")

#: Pairs per block of :func:`cells`.
BLOCK = 4_000_000


@dataclass(frozen=True)
class Kernel:
    """``viable`` (Q_V, bool over states x actions), ``kernel`` (S_V, bool over states), ``measure``
    (float over states) and the ``rounds`` the iteration took."""

    viable: np.ndarray
    kernel: np.ndarray
    measure: np.ndarray
    rounds: int


def cells(next_state: np.ndarray, failed: np.ndarray, grids: list[np.ndarray]) -> np.ndarray:
    """The flat cell index (int32 or int64) of every pair's next state on ``grids``: per dimension
    ``np.digitize`` (0 below the grid, ``len(grid)`` above it), raveled over (len + 1) per
    dimension; a failed pair gets one index past the last cell (never viable). Computed in blocks of
    :data:`BLOCK` pairs, so the temporaries stay small beside the result."""
    shape = tuple(g.size + 1 for g in grids)
    total = int(np.prod(shape))
    dtype = np.int32 if total < 2**31 - 1 else np.int64
    out = np.empty(failed.shape, dtype=dtype)
    flat_out = out.reshape(-1)
    flat_failed = failed.reshape(-1)
    flat_next = next_state.reshape(-1, len(grids))
    for start in range(0, flat_failed.size, BLOCK):
        block = slice(start, start + BLOCK)
        bad = flat_failed[block]
        flat = np.zeros(bad.size, dtype=dtype)
        for dim, grid in enumerate(grids):
            x = np.where(bad, grid[0], flat_next[block, dim])
            flat = flat * dtype(shape[dim]) + np.digitize(x, grid).astype(dtype)
        flat[bad] = total
        flat_out[block] = flat
    return out


def cell_viable(kernel: np.ndarray, outside: str = "fail") -> np.ndarray:
    """Whether every node of each cell is in ``kernel`` (bool over states): a flat bool array over
    the cells (shape of the grid + 1 per dimension, raveled) plus one False for a failed pair."""
    ok = np.pad(kernel, 1, constant_values=(outside == "edge"))
    for axis in range(ok.ndim):
        lo = np.take(ok, range(ok.shape[axis] - 1), axis=axis)
        hi = np.take(ok, range(1, ok.shape[axis]), axis=axis)
        ok = lo & hi
    return np.append(ok.ravel(), False)


def viable_set(failed: np.ndarray, cell: np.ndarray, n_state_dims: int, outside: str = "fail") -> Kernel:
    """Q_V, S_V and the measure of a transition map (``failed`` and its ``cells``), iterated to
    the fixed point (module docstring)."""
    if outside not in OUTSIDE:
        raise ValueError(f"outside must be one of {', '.join(OUTSIDE)}, got {outside!r}")
    actions = tuple(range(n_state_dims, failed.ndim))
    q = ~failed
    s = q.any(axis=actions)
    rounds = 0
    while True:
        rounds += 1
        q = q & cell_viable(s, outside)[cell]
        s_new = q.any(axis=actions)
        if np.array_equal(s_new, s):
            break
        s = s_new
    return Kernel(q, s, q.mean(axis=actions), rounds)


def is_fixed_point(failed: np.ndarray, cell: np.ndarray, kernel: np.ndarray, outside: str = "fail") -> bool:
    """Whether ``kernel`` is its own image: the states with a non-failing action whose cell is
    viable under ``kernel`` are exactly ``kernel``."""
    actions = tuple(range(kernel.ndim, failed.ndim))
    image = (~failed & cell_viable(kernel, outside)[cell]).any(axis=actions)
    return bool(np.array_equal(image, kernel))
