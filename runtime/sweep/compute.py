"""One chunk of a sweep, computed with the public batch API (:func:`slipmaps.apex_return_batch`,
:func:`slipmaps.stance_batch`): the same rows, values and statuses as calling it directly.

The batch API takes one parameter set per call, so a chunk's rows are grouped by their swept
parameter values (one call per distinct set: a grid, whose parameter axes vary slowest, has a few per
chunk; a random sweep over parameters has one per row, a Python call each). A row whose
parameters are invalid together (``q_r_td > l0``) is ``INVALID_INPUT`` with NaN outputs, as the batch
API treats a bad row.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from slipmaps.generated.status import Status

from ..api.frames import status_names
from ..api.maps import apex_return_batch, stance_batch
from .axes import KINDS
from .spec import Sweep, slip_params

__all__ = ["Chunk", "compute", "compute_rows", "status_names"]

_NAMES = {int(s): s.name for s in Status}


@dataclass(frozen=True)
class Chunk:
    """Rows ``start..start+rows-1`` of a sweep: ``columns`` in the sweep's column order (``status``
    the int64 codes; ``status_name`` is derived when written)."""

    index: int
    start: int
    columns: dict[str, np.ndarray]

    @property
    def rows(self) -> int:
        return len(self.columns["status"])

    def counts(self) -> dict[str, int]:
        """Rows per status name."""
        codes, counts = np.unique(self.columns["status"], return_counts=True)
        return {_NAMES[int(c)]: int(k) for c, k in zip(codes, counts, strict=True)}


def compute(sweep: Sweep, index: int) -> Chunk:
    """Chunk ``index`` of ``sweep``."""
    start, stop = sweep.chunk_bounds(index)
    return Chunk(index, start, compute_rows(sweep, start, stop))


def _groups(sweep: Sweep, points: dict[str, np.ndarray], n: int):
    """(rows, swept parameter values) per distinct parameter set; ``rows`` a slice where the set's
    rows are contiguous (a grid: parameter axes vary slowest), else an index array."""
    names = sweep.param_axes
    if not names:
        yield slice(0, n), {}
        return
    keys = np.column_stack([points[a] for a in names])
    uniq, inverse = np.unique(keys, axis=0, return_inverse=True)
    order = np.argsort(inverse.ravel(), kind="stable")
    ends = np.cumsum(np.bincount(inverse.ravel(), minlength=len(uniq)))
    begin = 0
    for g, end in enumerate(ends):
        rows = order[begin:end]
        if rows[-1] - rows[0] + 1 == len(rows):  # ascending (stable sort), so contiguous
            rows = slice(int(rows[0]), int(rows[-1]) + 1)
        yield rows, dict(zip(names, map(float, uniq[g]), strict=True))
        begin = end


def compute_rows(sweep: Sweep, start: int, stop: int) -> dict[str, np.ndarray]:
    """The columns of rows ``start..stop-1`` (all but ``status_name``)."""
    n = stop - start
    points = sweep.points(start, stop)
    fixed = dict(sweep.fixed)
    inputs = {
        name: points[name] if name in points else np.full(n, fixed.get(name, np.nan))
        for name in sweep.input_names
    }
    constants = {k: v for k, v in fixed.items() if k not in inputs}
    defaults = [q for q in KINDS[sweep.kind] if q.optional and q.name not in points and q.name not in fixed]
    outputs = {name: np.full(n, np.nan) for name in sweep.output_names}
    status = np.full(n, int(Status.INVALID_INPUT), dtype=np.int64)
    opts = dict(sweep.options)
    for rows, values in _groups(sweep, points, n):
        try:
            params = slip_params({**constants, **values})
        except ValueError:
            continue  # INVALID_INPUT, NaN outputs
        for q in defaults:  # an input left to its default (ground 0) or the parameters (a stance's q_r_td)
            inputs[q.name][rows] = getattr(params, q.name) if q.default is None else q.default
        if sweep.kind == "apex_return":
            args = {q: inputs[q][rows] for q in sweep.input_names}
            res = apex_return_batch(sweep.map, params, **args, progress=False, **opts)
        else:
            td = np.column_stack([inputs[q][rows] for q in sweep.input_names])
            res = stance_batch(sweep.map, params, td, progress=False, **opts)
        for name, column in outputs.items():
            column[rows] = res[name]
        status[rows] = res["status"]
    cols = {**inputs, **{a: points[a] for a in sweep.param_axes}}
    cols.update(outputs)
    cols["status"] = status
    return cols
