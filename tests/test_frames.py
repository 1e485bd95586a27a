"""Results as tables (runtime/api/frames.py): every result with rows gives 1-D columns, a pandas
DataFrame and an Arrow table, a row per point, vector values split into named columns, statuses by
name."""

from __future__ import annotations

import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.api.frames import flat_columns

P = slipmaps.HUMAN_RUNNER


def test_batch_result_to_pandas_has_a_row_per_point_and_status_names():
    h = np.array([[1.0, 1.05], [0.1, 1.02]])
    res = slipmaps.apex_return_batch("geyer", P, h, 5.0, 0.35)
    df = res.to_pandas()
    assert len(df) == 4 and list(df["status"]) == [
        slipmaps.Status(int(c)).name for c in res.status.reshape(-1)
    ]
    assert (df["status"] == "OK").sum() == 3 and df["status_code"].dtype.kind == "i"
    assert np.array_equal(
        df["next_apex_height"].to_numpy(), res["next_apex_height"].reshape(-1), equal_nan=True
    )
    assert {"liftoff_q_r", "liftoff_q_thd"} <= set(df.columns)
    table = res.to_arrow()
    assert table.num_rows == 4 and table.column_names == list(df.columns)


def test_jacobian_batch_to_pandas_names_every_derivative():
    jb = slipmaps.apex_return_jacobian_batch("geyer", P, [1.0, 1.05], 5.0, 0.35)
    df = jb.to_pandas()
    name = "d(next_apex_height)/d(touchdown_angle)"
    assert name in df.columns and len(df) == 2
    assert np.array_equal(df[name].to_numpy(), jb["next_apex_height", "touchdown_angle"])
    derivatives = [c for c in df.columns if c.startswith("d(")]
    assert len(derivatives) == len(jb.outputs) * len(jb.inputs)


def test_flat_columns_split_vectors_and_refuse_a_wrong_count_of_names():
    arrays = {"a": np.zeros((2, 3)), "v": np.ones((2, 3, 2))}
    cols = flat_columns(arrays, rank=2, components={"v": ("x", "y")})
    assert list(cols) == ["a", "x", "y"] and all(c.shape == (6,) for c in cols.values())
    with pytest.raises(ValueError, match="2 components, 3 names"):
        flat_columns({"v": np.ones((2, 2))}, rank=1, components={"v": ("x", "y", "z")})
