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
from ..analysis.viability_map import Transition
from ..api.params import SlipParams
from .run import sweep
from .spec import Sweep
from .store import iter_sweep

__all__ = ["viability_sweep"]


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
    progress: bool | None = None,
    **options,
) -> ViableSet:
    """The viable set, kernel and measure of map ``name`` (as :func:`slipmaps.viability` with
    ``apex_speed``), its transition map a resumable sweep into directory ``out`` (every output of
    every step, in ``format``: "parquet", which needs pyarrow, or "csv") on ``scheduler`` (None: this
    process; "local:N": a local Dask cluster of N workers; a scheduler address or a
    ``distributed.Client``). ``chunk_rows``: the sweep's rows per chunk (default the sweep's)."""
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
    # the rows in sweep order: (k_d,) h, v, angle, (rate); read back chunk by chunk
    order = tuple(len(v) for v in axes.values())
    n = int(np.prod(order))
    failed = np.empty(n, dtype=bool)
    status = np.empty(n, dtype=np.int8)
    nxt = np.empty((n, 2))
    row = 0
    for chunk in iter_sweep(out):
        k = len(chunk["status"])
        code = chunk["status"]
        h1, v1 = chunk["next_apex_height"], chunk["next_apex_speed"]
        bad = (code != int(Status.OK)) | ~(v1 > 0.0)
        failed[row : row + k] = bad
        status[row : row + k] = code
        nxt[row : row + k, 0] = np.where(bad, np.nan, h1)
        nxt[row : row + k, 1] = np.where(bad, np.nan, v1)
        row += k
    if row != n:
        raise ValueError(f"the sweep in {out} has {row} rows, the grid {n}: a directory of another sweep?")
    seconds = time.perf_counter() - start
    # to the study's axes: h, v, angle, (k_d), (rate)
    names = list(axes)
    wanted = ["apex_height", "apex_speed", "touchdown_angle"] + [
        a for a in ("k_d", "retraction_rate") if a in axes
    ]
    perm = [names.index(a) for a in wanted]

    def arrange(a, trailing=()):
        a = a.reshape(order + trailing)
        return np.ascontiguousarray(np.transpose(a, perm + list(range(len(order), a.ndim))))

    tm = Transition(arrange(failed), arrange(status), arrange(nxt, (2,)), seconds)
    return from_transition(call, params, grids, tm, outside, float(ground))
