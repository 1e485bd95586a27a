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

A transition map with axes the runner does not choose (an unknown ground) or chooses later (k_d at
the bottom, once the ground is known) gives Q_V as a monotone reduction of its steps (``choose``:
"for every ground", "some k_d for every ground"; :mod:`.viability_robust`), iterated the same way.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = [
    "OUTSIDE",
    "Kernel",
    "cell_dtype",
    "cells",
    "cell_viable",
    "is_fixed_point",
    "steps_into",
    "viable_set",
]

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


def cell_dtype(grids: list[np.ndarray]) -> type:
    """The integer type of :func:`cells` on ``grids``: int32 while the cells' indices fit."""
    return np.int32 if int(np.prod([g.size + 1 for g in grids])) < 2**31 - 1 else np.int64


def cells(next_state: np.ndarray, failed: np.ndarray, grids: list[np.ndarray]) -> np.ndarray:
    """The flat cell index (int32 or int64) of every pair's next state on ``grids``: per dimension
    ``np.digitize`` (0 below the grid, ``len(grid)`` above it), raveled over (len + 1) per
    dimension; a failed pair gets one index past the last cell (never viable). Computed in blocks of
    :data:`BLOCK` pairs, so the temporaries stay small beside the result."""
    shape = tuple(g.size + 1 for g in grids)
    total = int(np.prod(shape))
    dtype = cell_dtype(grids)
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


def viable_set(
    failed: np.ndarray,
    cell: np.ndarray,
    n_state_dims: int,
    outside: str = "fail",
    choose: Callable[[np.ndarray], np.ndarray] | None = None,
) -> Kernel:
    """Q_V, S_V and the measure of a transition map (``failed`` and its ``cells``), iterated to
    the fixed point (module docstring).

    ``choose`` makes Q_V of the steps whose next state is viable (a bool array shaped as
    ``failed``) when the transition map has axes beyond the actions (what the runner does not
    choose, or chooses later): it reduces them, and must keep the state axes first and be monotone
    (more viable steps never make fewer pairs viable). None: Q_V is those steps (every axis after
    the states an action). An unknown ground's axis ``u`` last: ``lambda ok: ok.all(axis=-1)``."""
    if outside not in OUTSIDE:
        raise ValueError(f"outside must be one of {', '.join(OUTSIDE)}, got {outside!r}")
    choose = choose or _identity
    ok = ~failed
    q = choose(ok)
    actions = tuple(range(n_state_dims, q.ndim))
    s = q.any(axis=actions)
    rounds = 0
    while True:
        rounds += 1
        ok &= cell_viable(s, outside)[cell]
        q = choose(ok)
        s_new = q.any(axis=actions)
        if np.array_equal(s_new, s):
            break
        s = s_new
    return Kernel(q, s, q.mean(axis=actions), rounds)


def _identity(ok: np.ndarray) -> np.ndarray:
    return ok


def steps_into(kernel: np.ndarray, failed: np.ndarray, cell: np.ndarray, outside: str = "fail") -> np.ndarray:
    """The steps (shaped as ``failed``) that do not fail and whose next state's cell is viable under
    ``kernel``."""
    return ~failed & cell_viable(kernel, outside)[cell]


def is_fixed_point(
    failed: np.ndarray,
    cell: np.ndarray,
    kernel: np.ndarray,
    outside: str = "fail",
    choose: Callable[[np.ndarray], np.ndarray] | None = None,
) -> bool:
    """Whether ``kernel`` is its own image: the states with a pair of Q_V (``choose`` of the steps
    into ``kernel``'s viable cells, as in :func:`viable_set`) are exactly ``kernel``."""
    q = (choose or _identity)(steps_into(kernel, failed, cell, outside))
    image = q.any(axis=tuple(range(kernel.ndim, q.ndim)))
    return bool(np.array_equal(image, kernel))
