"""One naming of the results' values (runtime/api/names.py): the next apex is ``next_apex_height``,
``next_apex_speed`` and the apex a step starts from ``apex_height``, ``apex_speed`` in every result
and table (scalar and batch results, Jacobians, sweeps, deadbeat batches, runs, swing policies); the
former names still read, equal to the new ones, with a DeprecationWarning naming the new name."""

from __future__ import annotations

import numpy as np
import pytest
import slipmaps
from slipmaps.generated import maps_index
from slipmaps.runtime.api import names
from slipmaps.runtime.api.results import APEX_RETURN, HALF, STANCE

P = slipmaps.HUMAN_RUNNER
SPEEDS = np.array([4.5, 5.0, 5.5])
ANGLES = np.array([[0.33], [0.36]])


def renamed(old: str, new: str):
    """The warning of a former name: names it, the new one and the release that removes it."""
    return pytest.warns(DeprecationWarning, match=rf"'{old}' .* to '{new}'.*slipmaps {names.REMOVED_IN}")


def test_the_rule_renames_the_next_apex_only_and_comes_from_the_index():
    assert names.RENAMED == {"apex_height": "next_apex_height", "apex_speed": "next_apex_speed"}
    assert names.RUN_RENAMED == {"next_height": "next_apex_height", "next_speed": "next_apex_speed"}
    kernel = [r["name"] for r in maps_index.APEX_OUTPUTS]
    assert APEX_RETURN == tuple(names.public(n) for n in kernel) and APEX_RETURN[:2] == tuple(
        names.RENAMED.values()
    )
    assert [names.kernel_name(n) for n in APEX_RETURN] == kernel
    # no stance or half-stance output is named like an input
    assert STANCE == tuple(r["name"] for r in maps_index.STANCE_OUTPUTS)
    assert HALF == tuple(r["name"] for r in maps_index.HALF_OUTPUTS)
    assert not set(APEX_RETURN) & set(names.INPUTS)


def test_a_scalar_result_names_the_next_apex_and_keeps_its_inputs():
    res = slipmaps.apex_return("geyer", P, 1.0, 5.0, 0.35, ground=0.02)
    assert res.ok and res.values["next_apex_height"] == res.next_apex_height == res["next_apex_height"]
    assert "apex_height" not in res.values and "apex_height" not in res.keys()
    assert {k: res.inputs[k] for k in names.INPUTS} == {
        "apex_height": 1.0,
        "apex_speed": 5.0,
        "touchdown_angle": 0.35,
        "ground": 0.02,
        "retraction_rate": 0.0,
    }
    with renamed("apex_height", "next_apex_height"):
        assert res.apex_height == res.next_apex_height
    with renamed("apex_speed", "next_apex_speed"):
        assert res["apex_speed"] == res.next_apex_speed
    assert res.as_dict()["values"]["next_apex_speed"] == res.next_apex_speed


def test_a_batch_carries_its_inputs_into_its_table():
    res = slipmaps.apex_return_batch("geyer", P, 1.0, SPEEDS, ANGLES)
    assert res.shape == (2, 3) and res.ok.all()
    assert {k: v.shape for k, v in res.inputs.items()} == dict.fromkeys(names.INPUTS, (2, 3))
    assert np.array_equal(res.inputs["apex_speed"], np.broadcast_to(SPEEDS, (2, 3)))
    df = res.to_pandas()
    assert list(df.columns[: len(names.INPUTS)]) == list(names.INPUTS)
    assert list(df.columns[len(names.INPUTS) :]) == [*res.names, "status", "status_code"]
    assert np.array_equal(df["apex_height"], np.ones(6)) and np.array_equal(df["ground"], np.zeros(6))
    assert np.array_equal(df["touchdown_angle"], np.repeat(ANGLES[:, 0], 3))
    assert np.array_equal(df["next_apex_height"], res["next_apex_height"].reshape(-1))
    assert res.to_arrow().column_names == list(df.columns)
    assert "apex_height" not in res and "next_apex_height" in res and "liftoff" in res
    with renamed("apex_height", "next_apex_height"):
        assert np.array_equal(res["apex_height"], res["next_apex_height"])


def test_stance_and_half_batches_carry_their_start_states():
    td = np.array([[1.0, -1.5, 0.35, -4.5], [1.0, -1.4, 0.33, -4.4]])
    df = slipmaps.stance_batch("geyer", P, td).to_pandas()
    assert list(df.columns[:4]) == list(maps_index.TOUCHDOWN) and np.array_equal(df[list(df.columns[:4])], td)
    half = slipmaps.half_stance_batch("iterative-compression", P, td)
    assert np.array_equal(np.column_stack(list(half.inputs.values())), td)


def test_jacobian_rows_name_the_next_apex_and_its_columns_the_inputs():
    jac = slipmaps.apex_return_jacobian("geyer", P, 1.0, 5.0, 0.35)
    assert jac.outputs[:2] == ("next_apex_height", "next_apex_speed")
    assert jac.inputs[:2] == ("apex_height", "apex_speed")
    d = jac["next_apex_height", "apex_height"]
    with renamed("apex_height", "next_apex_height"):
        assert jac["apex_height", "apex_height"] == d
    jb = slipmaps.apex_return_jacobian_batch("geyer", P, [1.0, 1.05], 5.0, 0.35)
    df = jb.to_pandas()
    assert list(df.columns[:2]) == ["apex_height", "apex_speed"]
    assert np.array_equal(df["d(next_apex_height)/d(apex_height)"], jb["next_apex_height", "apex_height"])


def test_sweeps_and_batches_use_the_same_names():
    sw = slipmaps.Sweep("geyer", {"apex_speed": [4.5, 5.0]}, {"apex_height": 1.0, "touchdown_angle": 0.35})
    df = slipmaps.apex_return_batch("geyer", P, 1.0, SPEEDS, 0.35).to_pandas()
    assert sw.output_names == tuple(df.columns[len(names.INPUTS) : -2])
    assert set(sw.columns) - {"status_name"} <= set(df.columns) | {"status"}


def test_deadbeat_batch_table_has_the_inputs_and_the_predicted_step():
    h, v = np.array([1.0, 1.0, 0.3]), np.array([5.0, 4.8, 2.0])
    batch = slipmaps.deadbeat_batch("iterative", P, h, v, 1.0, 5.2)
    assert batch.counts() == {"REACHED": 1, "UNREACHABLE": 1, "MAP_FAILED": 1}
    df = batch.to_pandas()
    assert list(df.columns[:4]) == ["apex_height", "apex_speed", "ground", "retraction_rate"]
    assert np.array_equal(df["apex_height"], h) and np.array_equal(df["apex_speed"], v)
    assert list(df["status"]) == ["REACHED", "UNREACHABLE", "MAP_FAILED"]
    assert list(df["status_code"]) == [0, 1, 2] and list(df["map_status"]) == ["OK", "OK", "APEX_TOO_LOW"]
    step = slipmaps.apex_return_batch("iterative", P, 1.0, 5.0, 0.35)
    assert set(step.names) <= set(df.columns)  # the prediction, by the map's result names
    assert np.array_equal(df["next_apex_speed"], batch["next_apex_speed"], equal_nan=True)
    assert "apex_height" not in batch
    with renamed("apex_speed", "next_apex_speed"):
        assert np.array_equal(batch["apex_speed"], batch["next_apex_speed"], equal_nan=True)
    with renamed("next_t_stance", "t_stance"):  # the prediction's former column names
        assert np.array_equal(batch["next_t_stance"], batch["t_stance"], equal_nan=True)
    one = slipmaps.deadbeat("iterative", P, 1.0, 5.0, 1.0, 5.2)
    assert one.inputs == {"apex_height": 1.0, "apex_speed": 5.0, "ground": 0.0, "retraction_rate": 0.0}
    assert one.next_apex_speed == batch["next_apex_speed"][0]
    with renamed("apex_speed", "next_apex_speed"):
        assert one.apex_speed == one.next_apex_speed
    d = one.as_dict()
    assert (d["apex_speed"], d["next_apex_speed"]) == (5.0, one.next_apex_speed)


def test_the_bottom_stage_names_the_next_apex():
    td = (1.0, -1.5, 0.36, -4.5)
    bottom = slipmaps.half_stance("exact-compression", P, td).end
    stage = slipmaps.BottomDeadbeat("iterative-decompression", P, aim="height")
    res = stage.plan(bottom, 1.0, 5.2)
    with renamed("apex_height", "next_apex_height"):
        assert res.apex_height == res.next_apex_height
    cols = stage.plan_batch(np.array([bottom]), 1.0, 5.2)
    assert cols["next_apex_height"][0] == res.next_apex_height and "apex_height" not in cols
    with renamed("apex_height", "next_apex_height"):
        assert cols["apex_height"][0] == res.next_apex_height
