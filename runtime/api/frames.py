"""Results as tables: a dict of 1-D columns, a pandas DataFrame, an Arrow table.

Every result with rows (:class:`~.results.BatchResult`, :class:`~.jacobian.JacobianBatch`, a
control :class:`~slipmaps.runtime.control.runs.Run`, a sweep's :func:`read_sweep`) gives
``columns()``: a dict of 1-D arrays, a row per point (C order of the input shape), a vector value
split into a column per component (``liftoff_q_r``, ... ; ``<name>_<i>`` where the components have
no names), the status as its name (``status``) and its code (``status_code``). ``to_pandas()`` and
``to_arrow()`` build on it. pandas and pyarrow are optional (``pip install 'slipmaps[pandas]'``,
``'slipmaps[parquet]'``): a missing one is an ImportError naming the extra.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from slipmaps.generated.status import Status

__all__ = ["flat_columns", "status_columns", "status_names", "to_arrow", "to_pandas"]

_CODES = {int(s): s.name for s in Status}
#: The name of every code from 0 to the largest (a gap, if the codes had one, by its number).
_TABLE = np.array([_CODES.get(i, str(i)) for i in range(max(_CODES) + 1)])


def status_names(codes: np.ndarray) -> np.ndarray:
    """The :class:`~slipmaps.Status` name of each code (a numpy string array of the codes' shape)."""
    return _TABLE[np.asarray(codes, dtype=np.int64)]


def status_columns(codes: np.ndarray, prefix: str = "status") -> dict[str, np.ndarray]:
    """``{prefix: names, prefix_code: codes}`` of int64 status codes (any shape, flattened)."""
    codes = np.asarray(codes, dtype=np.int64).reshape(-1)
    return {prefix: status_names(codes), f"{prefix}_code": codes}


def flat_columns(
    columns: Mapping[str, np.ndarray], rank: int, components: Mapping[str, Sequence[str]] | None = None
) -> dict[str, np.ndarray]:
    """Columns of ``rank`` leading (row) axes flattened to 1-D; an array with more axes split into a
    column per component (named by ``components[name]`` where given, else ``<name>_<i>``)."""
    out: dict[str, np.ndarray] = {}
    for name, value in columns.items():
        arr = np.asarray(value)
        rows = int(np.prod(arr.shape[:rank], dtype=np.int64))
        flat = arr.reshape(rows, -1)
        if arr.ndim == rank:
            out[name] = flat[:, 0]
            continue
        names = (components or {}).get(name) or [f"{name}_{i}" for i in range(flat.shape[1])]
        if len(names) != flat.shape[1]:
            raise ValueError(f"column {name!r} has {flat.shape[1]} components, {len(names)} names given")
        for j, sub in enumerate(names):
            out[sub] = flat[:, j]
    return out


def to_pandas(columns: Mapping[str, np.ndarray]):
    """A pandas DataFrame of 1-D ``columns`` (ImportError naming the extra without pandas)."""
    try:
        import pandas as pd
    except ImportError:
        raise ImportError("to_pandas() needs pandas: pip install 'slipmaps[pandas]'") from None
    return pd.DataFrame(dict(columns))


def to_arrow(columns: Mapping[str, np.ndarray]):
    """A pyarrow Table of 1-D ``columns`` (ImportError naming the extra without pyarrow)."""
    try:
        import pyarrow as pa
    except ImportError:
        raise ImportError("to_arrow() needs pyarrow: pip install 'slipmaps[parquet]'") from None
    return pa.table({k: pa.array(v) for k, v in columns.items()})
