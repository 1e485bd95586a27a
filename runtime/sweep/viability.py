"""Viability on the sweep machinery: the transition map as a sweep (resumable, chunks on Dask).

:func:`viability_sweep` is :func:`slipmaps.viability` with its transition map computed by
:func:`slipmaps.sweep` into a directory ``out``: a grid of ``k_d`` (slowest), ``apex_height``,
``apex_speed``, ``touchdown_angle`` and ``retraction_rate``, chunk by chunk, in this process or on a
Dask cluster (``scheduler="local:2"`` or an address); running it again into the same ``out`` resumes
(the chunks written are kept). The chunks are then read back one at a time into the study's arrays,
and the discretisation and fixed point are :func:`slipmaps.viability`'s. The state is the apex height
and speed: a sweep's axes are independent, so the speed on a fixed energy level (which depends on
the height) is not a sweep; give such a grid to :func:`slipmaps.viability`.
"""

from __future__ import annotations

import time

import numpy as np
from slipmaps.generated.status import Status

from ..analysis.viability import ViableSet, checked, from_transition
from ..analysis.viability_kernel import cell_dtype, cells
from ..analysis.viability_map import Transition
from ..api.params import SlipParams
from .run import sweep
from .spec import Sweep
from .store import iter_sweep

__all__ = ["viability_sweep"]

#: The columns of the sweep's files a study reads.
COLUMNS = ("status", "next_apex_height", "next_apex_speed")


def viability_sweep(
    name: str,
    params: SlipParams,
    *,
    apex_height,
    apex_speed,
    touchdown_angle,
    out,
    k_d=None,
    retraction_rate=None,
    ground: float = 0.0,
    scheduler=None,
    format: str = "parquet",
    chunk_rows: int | None = None,
    outside: str = "fail",
    next_state_dtype="float64",
    progress: bool | None = None,
    **options,
) -> ViableSet:
    """The viable set, kernel and measure of map ``name`` (as :func:`slipmaps.viability` with
    ``apex_speed``), its transition map a resumable sweep into directory ``out`` (every output of
    every step, in ``format``: "parquet", which needs pyarrow, or "csv") on ``scheduler`` (None: this
    process; "local:N": a local Dask cluster of N workers; a scheduler address or a
    ``distributed.Client``). ``chunk_rows``: the sweep's rows per chunk (default the sweep's).

    Only the status and the next apex of the sweep's files are read back, a chunk at a time, each
    row into its place in the study's arrays: this process holds them (the fixed point needs all
    pairs) and the workers a chunk each. ``next_state_dtype="float32"`` halves the largest of them
    (``next_state``: 8 bytes per pair instead of 16 on a (height, speed) grid); the cells are
    computed from the float64 values as they are read, so the sets are the same either way."""
    dtype = np.dtype(next_state_dtype)
    if dtype not in (np.float64, np.float32):
        raise ValueError(f"next_state_dtype must be float64 or float32, got {next_state_dtype!r}")
    if "energy" in options:
        raise ValueError(
            "a sweep's axes are independent, and the speed on a fixed energy level depends on the height: "
            "give apex_speed, or use slipmaps.viability(..., energy=...)"
        )
    grids, call = checked(
        name, params, apex_height, touchdown_angle, apex_speed, None, k_d, retraction_rate, outside, options
    )
    axes = {}
    if "k_d" in grids.actions:
        axes["k_d"] = grids.actions["k_d"].tolist()
    axes["apex_height"] = grids.states["apex_height"].tolist()
    axes["apex_speed"] = grids.states["apex_speed"].tolist()
    axes["touchdown_angle"] = grids.actions["touchdown_angle"].tolist()
    if "retraction_rate" in grids.actions:
        axes["retraction_rate"] = grids.actions["retraction_rate"].tolist()
    definition = Sweep(
        name,
        axes,
        {"ground": float(ground)},
        params=params,
        options=options,
        chunk_rows=chunk_rows,
    )
    start = time.perf_counter()
    summary = sweep(definition, out, format=format, scheduler=scheduler, progress=progress)
    if not summary.complete:  # pragma: no cover - sweep() computes every chunk unless max_chunks
        raise RuntimeError(f"the sweep in {out} is not complete")
    # the rows in sweep order, (k_d,) h, v, angle, (rate), read back chunk by chunk, each row put
    # at its place in the study's order, h, v, angle, (k_d), (rate), and its cell computed from the
    # float64 next state (so a float32 next_state gives the same sets)
    names = list(axes)
    wanted = ["apex_height", "apex_speed", "touchdown_angle"] + [
        a for a in ("k_d", "retraction_rate") if a in axes
    ]
    perm = [names.index(a) for a in wanted]
    order = tuple(len(v) for v in axes.values())
    shape = tuple(order[i] for i in perm)
    n = int(np.prod(order))
    failed = np.empty(n, dtype=bool)
    status = np.empty(n, dtype=np.int8)
    nxt = np.empty((n, 2), dtype=dtype)
    cell = np.empty(n, dtype=cell_dtype(list(grids.states.values())))
    row = 0
    for chunk in iter_sweep(out, COLUMNS):
        k = len(chunk["status"])
        if row + k > n:
            break
        code = chunk["status"]
        step = np.stack([chunk["next_apex_height"], chunk["next_apex_speed"]], axis=-1)
        bad = (code != int(Status.OK)) | ~(step[:, 1] > 0.0)
        step[bad] = np.nan
        index = np.unravel_index(np.arange(row, row + k), order)
        at = np.ravel_multi_index(tuple(index[i] for i in perm), shape)
        failed[at] = bad
        status[at] = code
        nxt[at] = step
        cell[at] = cells(step, bad, list(grids.states.values()))
        row += k
    if row != n:
        raise ValueError(f"the sweep in {out} has more or fewer rows than the grid's {n}: another sweep's?")
    seconds = time.perf_counter() - start
    tm = Transition(failed.reshape(shape), status.reshape(shape), nxt.reshape(*shape, 2), seconds)
    return from_transition(call, params, grids, tm, outside, float(ground), cell.reshape(shape))
