"""Sweeps (runtime/sweep*.py): rows equal to direct batch calls, files with names and units, resuming,
refusing a different sweep, flat memory, the CLI, and a two-worker Dask LocalCluster (equal to the
in-process result; a worker killed mid-sweep loses nothing)."""

from __future__ import annotations

import json
import os
import signal
import sys
import tracemalloc
from pathlib import Path

import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.cli.app import main
from slipmaps.runtime.sweep import files as sweep_files
from slipmaps.runtime.sweep.compute import compute
from slipmaps.runtime.sweep.run import load, sweep
from slipmaps.runtime.sweep.spec import Sweep
from slipmaps.runtime.sweep.store import read_sweep

P = slipmaps.HUMAN_RUNNER
EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "sweep.toml"
SPEEDS = {"low": 3.0, "high": 7.0, "num": 7}
ANGLES = [0.25, 0.35, 0.45]
APEX = {"apex_height": 1.0, "apex_speed": 5.0, "touchdown_angle": 0.3}


def same(a: np.ndarray, b: np.ndarray) -> bool:
    """Equal row for row, bit for bit, NaN where the other is NaN."""
    return a.shape == b.shape and bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))


def assert_rows(got: dict, sw: Sweep, res, inputs: dict) -> None:
    """The sweep's columns equal a direct batch result ``res`` (flattened) and its inputs."""
    for name, values in inputs.items():
        assert same(got[name], np.ravel(values)), name
    for name in sw.output_names:
        assert same(got[name], np.ravel(res[name])), name
    assert np.array_equal(got["status"], np.ravel(res["status"]))
    assert list(got["status_name"]) == [slipmaps.Status(int(s)).name for s in np.ravel(res["status"])]


def grid_sweep(**kw) -> Sweep:
    axes = {"m": [70.0, 80.0], "apex_speed": SPEEDS, "touchdown_angle": ANGLES}
    return Sweep("geyer", axes, {"apex_height": 1.0}, chunk_rows=kw.pop("chunk_rows", 10), **kw)


def test_grid_sweep_equals_direct_batch_calls(tmp_path):
    sw = grid_sweep()
    assert sw.rows == 42 and sw.chunks == 5  # 2 x 7 x 3, the last chunk short
    summary = sweep(sw, tmp_path / "g")
    assert summary.complete and summary.rows_done == 42 and sum(summary.counts.values()) == 42
    got = read_sweep(tmp_path / "g")
    assert tuple(got) == sw.columns
    speeds = np.linspace(3.0, 7.0, 7)
    for j, m in enumerate((70.0, 80.0)):  # parameter axes vary slowest, then the inputs in order
        res = slipmaps.apex_return_batch("geyer", P.with_(m=m), 1.0, speeds[:, None], np.array(ANGLES))
        part = {k: v[21 * j : 21 * (j + 1)] for k, v in got.items()}
        inputs = {
            "apex_speed": np.repeat(speeds, 3),
            "touchdown_angle": np.tile(ANGLES, 7),
            "m": np.full(21, m),
        }
        assert_rows(part, sw, res, inputs)
    assert summary.counts == dict(zip(*np.unique(got["status_name"], return_counts=True), strict=True))
    frame = read_sweep(tmp_path / "g", frame=True)  # pandas: in the test extra
    assert list(frame.columns) == list(got) and len(frame) == 42
    assert np.array_equal(frame["status"].to_numpy(), got["status"])


def test_random_sweep_equals_direct_batch_calls(tmp_path):
    axes = {"apex_speed": {"low": 3.0, "high": 7.0}, "touchdown_angle": {"low": 0.2, "high": 0.45}}
    sw = Sweep("geyer", axes, {"apex_height": 1.0}, mode="random", samples=50, seed=7, chunk_rows=16)
    sweep(sw, tmp_path / "r")
    got = read_sweep(tmp_path / "r")
    pts = sw.points(0, 50)
    assert 3.0 <= pts["apex_speed"].min() and pts["apex_speed"].max() <= 7.0
    res = slipmaps.apex_return_batch("geyer", P, 1.0, pts["apex_speed"], pts["touchdown_angle"])
    assert_rows(got, sw, res, pts)
    # A row does not depend on the chunk it falls in; another seed is another sample.
    other = Sweep("geyer", axes, {"apex_height": 1.0}, mode="random", samples=50, seed=7, chunk_rows=7)
    parts = [other.points(*other.chunk_bounds(i)) for i in range(other.chunks)]
    assert same(np.concatenate([p["apex_speed"] for p in parts]), pts["apex_speed"])
    reseeded = Sweep("geyer", axes, {"apex_height": 1.0}, mode="random", samples=50, seed=8)
    assert not np.array_equal(reseeded.points(0, 50)["apex_speed"], pts["apex_speed"])


def test_random_parameters_and_stiffness_ratio_equal_per_row_calls():
    axes = {"k_d_over_k_c": {"low": 0.8, "high": 1.25}, "apex_speed": {"low": 4.0, "high": 6.0}}
    sw = Sweep("geyer-vs", axes, {"apex_height": 1.0, "touchdown_angle": 0.35}, mode="random", samples=9)
    chunk = compute(sw, 0).columns
    for i in range(9):
        params = P.with_(k_d=P.k_c * chunk["k_d_over_k_c"][i])
        one = slipmaps.apex_return("geyer-vs", params, 1.0, chunk["apex_speed"][i], 0.35)
        assert one.status == chunk["status"][i]
        assert same(np.array([chunk["next_apex_speed"][i]]), np.array([one.next_apex_speed]))


def test_stance_and_exact_sweeps_equal_direct_batch_calls():
    axes = {"q_thd_td": [-4.0, -5.0], "q_th_td": [0.3, 0.4]}
    sw = Sweep("iterative", axes, {"q_rd_td": -1.5}, kind="stance", options={"iterations": 3})
    got = compute(sw, 0).columns
    td = np.array([[1.0, -1.5, th, thd] for thd in (-4.0, -5.0) for th in (0.3, 0.4)])
    res = slipmaps.stance_batch("iterative", P, td, iterations=3)
    assert_rows(
        {**got, "status_name": sweep_files.status_names(got["status"])}, sw, res, {"q_r_td": td[:, 0]}
    )
    ex = Sweep("exact", {"apex_speed": [4.0, 6.0]}, {"apex_height": 1.0, "touchdown_angle": 0.35})
    got = compute(ex, 0).columns
    res = slipmaps.apex_return_batch("exact", P, 1.0, np.array([4.0, 6.0]), 0.35)
    assert_rows({**got, "status_name": sweep_files.status_names(got["status"])}, ex, res, {})


def test_csv_and_parquet_round_trip_with_names_and_units(tmp_path):
    sw = grid_sweep(chunk_rows=100)
    files = {}
    for fmt in ("csv", "parquet"):
        summary = sweep(sw, tmp_path / fmt, format=fmt, combine=True)
        files[fmt] = summary.combined
        manifest = json.loads((tmp_path / fmt / "manifest.json").read_text())
        assert manifest["sha256"] == sw.digest(fmt) and manifest["columns"] == list(sw.columns)
    units = {name: d["unit"] for name, d in sw.described().items()}
    assert units["apex_speed"] == "m/s" and units["m"] == "kg" and units["next_apex_height"] == "m"
    csv_cols, csv_units = sweep_files.read(files["csv"])
    pq_cols, pq_units = sweep_files.read(files["parquet"])
    assert tuple(csv_cols) == tuple(pq_cols) == sw.columns
    assert csv_units == pq_units == units
    for name in sw.columns:
        a, b = csv_cols[name], pq_cols[name]
        assert np.array_equal(a, b) if a.dtype.kind in "iU" else same(a, b), name
    # Without pyarrow the CSV writer is Python's: other spellings, the same values.
    chunk = compute(sw, 0)
    plain = sweep_files.encode(sw, "csv", "h", chunk, use_pyarrow=False)
    (tmp_path / "plain.csv").write_bytes(plain)
    for name, values in sweep_files.read(tmp_path / "plain.csv")[0].items():
        ref = csv_cols[name]
        assert np.array_equal(values, ref) if ref.dtype.kind in "iU" else same(values, ref), name


def test_without_the_extras_errors_name_them_and_csv_still_works(tmp_path, monkeypatch):
    for mod in ("pyarrow", "pyarrow.csv", "pyarrow.parquet", "distributed"):
        monkeypatch.setitem(sys.modules, mod, None)  # import fails as if it were not installed
    with pytest.raises(ValueError, match=r"needs dask.distributed: pip install 'slipmaps\[dask\]'"):
        sweep(grid_sweep(), tmp_path / "d", scheduler="local:2")
    with pytest.raises(ValueError, match=r"need pyarrow: pip install 'slipmaps\[parquet\]'"):
        sweep(grid_sweep(), tmp_path / "p", format="parquet")
    assert not (tmp_path / "p").exists()  # refused before anything was written
    assert sweep(grid_sweep(), tmp_path / "c").rows_done == 42  # CSV by Python's writer


def test_an_interrupted_sweep_resumes_to_the_same_files(tmp_path):
    sw = grid_sweep()
    sweep(sw, tmp_path / "whole")

    def stop_after_two(index, seen=[]):  # noqa: B006 - a counter for this test only
        seen.append(index)
        if len(seen) == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sweep(sw, tmp_path / "cut", on_chunk=stop_after_two)
    (tmp_path / "cut" / "chunks" / ".part-00004.csv.tmp").write_text("half a chunk")  # cut mid-write
    part = sweep(sw, tmp_path / "cut", max_chunks=1)
    assert (part.chunks_done, part.chunks_new, part.complete) == (3, 1, False)
    rest = sweep(sw, tmp_path / "cut")
    assert (rest.chunks_new, rest.rows_new, rest.complete, rest.rows_done) == (2, 12, True, 42)
    whole = sorted(p.name for p in (tmp_path / "whole" / "chunks").iterdir())
    assert sorted(p.name for p in (tmp_path / "cut" / "chunks").iterdir()) == whole
    for name in whole:
        assert (tmp_path / "cut" / "chunks" / name).read_bytes() == (
            tmp_path / "whole" / "chunks" / name
        ).read_bytes()
    assert json.loads((tmp_path / "cut" / "summary.json").read_text())["counts"] == rest.counts


def test_progress_bar_on_request(tmp_path, capsys):
    sweep(grid_sweep(), tmp_path / "p", progress=True)
    err = capsys.readouterr().err
    assert "sweep geyer: [" in err and "42/42 rows" in err and err.endswith("\n")
    sweep(grid_sweep(), tmp_path / "q", progress=None)  # not a terminal: no bar
    assert capsys.readouterr().err == ""


def test_a_different_sweep_is_refused(tmp_path):
    sweep(grid_sweep(), tmp_path / "a", max_chunks=1)
    other = Sweep(
        "geyer", {"apex_speed": SPEEDS}, {"apex_height": 1.0, "touchdown_angle": 0.3}, chunk_rows=10
    )
    with pytest.raises(ValueError, match=r"holds a different sweep \(it differs in axes, fixed\)"):
        sweep(other, tmp_path / "a")
    with pytest.raises(ValueError, match=r"differs in format"):
        sweep(grid_sweep(), tmp_path / "a", format="parquet")
    with pytest.raises(ValueError, match=r"differs in chunk_rows"):
        sweep(grid_sweep(chunk_rows=11), tmp_path / "a")
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "notes.txt").write_text("mine")
    with pytest.raises(ValueError, match="holds no sweep"):
        sweep(grid_sweep(), tmp_path / "b")
    assert sorted(p.name for p in (tmp_path / "b").iterdir()) == ["notes.txt"]


@pytest.mark.parametrize(
    ("axes", "fixed", "kw", "message"),
    [
        ({"apex_sped": [1.0]}, {}, {}, "unknown sweep quantity 'apex_sped'"),
        ({"apex_speed": [5.0]}, {"apex_speed": 5.0}, {}, "both fixed and swept"),
        ({"apex_speed": [5.0]}, {"apex_height": 1.0}, {}, "needs touchdown_angle"),
        ({"apex_height": [-1.0, 1.0]}, {"apex_speed": 5, "touchdown_angle": 0.3}, {}, "must not be negative"),
        ({"k_d_over_k_c": [0.9, 1.1]}, APEX, {}, "cannot sweep k_d_over_k_c; sweep k instead"),
        ({"k": [1e4, 2e4]}, {"k_d_over_k_c": 1.2, **APEX}, {}, "needs a constant leg stiffness"),
        ({"k": [1e4]}, {"k_c": 2e4, **APEX}, {}, "either k"),
        ({"m": [70.0]}, {"q_r_td": 1.1, **APEX}, {}, "must not exceed the rest length"),
        ({"apex_speed": {"low": 3, "high": 7}}, {"apex_height": 1, "touchdown_angle": 0.3}, {}, "needs num"),
        ({"apex_speed": [5.0]}, {"apex_height": 1, "touchdown_angle": 0.3}, {"mode": "random"}, "samples"),
        ({"apex_speed": "3:7:x"}, {"apex_height": 1, "touchdown_angle": 0.3}, {}, "not a number"),
    ],
)
def test_definition_errors_name_the_problem(axes, fixed, kw, message):
    with pytest.raises(ValueError, match=message):
        Sweep("geyer", axes, fixed, **kw)


def test_memory_stays_flat_for_1e8_rows(tmp_path):
    axes = {
        "apex_speed": {"low": 3.0, "high": 7.0, "num": 10_000},
        "touchdown_angle": {"low": 0.2, "high": 0.45, "num": 10_000},
    }
    sw = Sweep("geyer", axes, {"apex_height": 1.0}, chunk_rows=20_000, mode="grid")
    assert sw.rows == 10**8 and sw.chunks == 5000
    last = sw.points(10**8 - 2, 10**8)
    assert list(last["apex_speed"]) == [7.0, 7.0] and last["touchdown_angle"][-1] == 0.45
    sweep(sw, tmp_path / "big", format="parquet", max_chunks=1)  # imports and compiles outside the count
    tracemalloc.start()
    summary = sweep(sw, tmp_path / "big", format="parquet", max_chunks=4)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert summary.rows_done == 100_000 and summary.chunks_new == 4 and not summary.complete
    # Measured 7.4e6 bytes at the peak of four chunks of 20 000 rows (one chunk's 16 columns are
    # 2.6e6 bytes); the whole sweep's columns would be 1.3e10.
    assert peak < 2e7, peak


def test_cli_sweep_and_the_toml_example(tmp_path, capsys):
    sw, run = load(EXAMPLE)
    assert sw.map == "gravity-type5" and sw.rows == 3 * 81 * 41 and run["format"] == "parquet"
    argv = ["sweep", "--map", "geyer", "--fixed", "apex_height=1", "--axis", "apex_speed=3:7:5"]
    argv += ["--axis", "touchdown_angle=0.3,0.35", "--out", str(tmp_path / "c"), "--no-progress"]
    assert main(argv) == 0
    assert "sweep of geyer: 10 of 10 rows (complete)" in capsys.readouterr().out
    assert main([*argv[:-3], "--out", str(tmp_path / "c"), "--chunk-rows", "3"]) == 2
    assert "holds a different sweep (it differs in chunk_rows)" in capsys.readouterr().err
    assert main(["sweep", "--map", "geyer", "--axis", "apex_speed=3:7:5", "--out", str(tmp_path / "d")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "needs apex_height, touchdown_angle" in err


def test_cli_interrupted_sweep_says_how_to_resume(tmp_path, capsys, monkeypatch):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr("slipmaps.runtime.sweep.run.sweep", interrupted)
    argv = ["sweep", "--map", "geyer", "--fixed", "apex_height=1", "--fixed", "touchdown_angle=0.3"]
    assert main([*argv, "--axis", "apex_speed=3,4", "--out", str(tmp_path / "i")]) == 130
    assert "run the same command again to resume" in capsys.readouterr().err


# -- Dask ----------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def cluster():
    """Two worker processes of one thread each; numba's cache on disk is warmed here first."""
    distributed = pytest.importorskip("distributed")
    compute(grid_sweep(), 0)  # compiles (or loads) the kernels into the on-disk cache
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
        ) as lc,
        distributed.Client(lc) as client,
    ):
        client.run(compute, grid_sweep(), 0)  # each worker loads them before the tests time anything
        yield client


def kill_test_sweep() -> Sweep:
    axes = {
        "apex_speed": {"low": 3.0, "high": 7.0, "num": 400},
        "touchdown_angle": {"low": 0.2, "high": 0.45, "num": 200},
    }
    return Sweep("geyer", axes, {"apex_height": 1.0}, chunk_rows=10_000)


def test_dask_sweep_equals_in_process(tmp_path, cluster):
    sw = grid_sweep(chunk_rows=4)
    here = sweep(sw, tmp_path / "here")
    there = sweep(sw, tmp_path / "there", scheduler=cluster)
    assert (there.counts, there.rows_done) == (here.counts, 42)
    for name in sorted(p.name for p in (tmp_path / "here" / "chunks").iterdir()):
        assert (tmp_path / "there" / "chunks" / name).read_bytes() == (
            tmp_path / "here" / "chunks" / name
        ).read_bytes()


def test_a_worker_killed_mid_sweep_loses_nothing(tmp_path, cluster):
    sw = kill_test_sweep()
    killed = []

    def kill_a_busy_worker(index):
        if killed:
            return
        busy = [w for w, keys in cluster.processing().items() if keys]
        if not busy:
            return  # try again after the next chunk
        pids = cluster.run(os.getpid)
        os.kill(pids[busy[0]], signal.SIGKILL)  # the nanny starts a new worker
        killed.append(busy[0])

    there = sweep(sw, tmp_path / "there", scheduler=cluster, on_chunk=kill_a_busy_worker)
    assert killed and there.complete and there.rows_done == sw.rows == 80_000
    got = read_sweep(tmp_path / "there")
    res = slipmaps.apex_return_batch(
        "geyer", P, 1.0, np.linspace(3.0, 7.0, 400)[:, None], np.linspace(0.2, 0.45, 200)
    )
    assert_rows(got, sw, res, {})


def test_cli_a_huge_sweep_states_its_estimate_and_needs_yes(tmp_path, capsys, monkeypatch):
    """10^4 x 10^4 rows (a plausible typo) is refused before anything is written, with its size;
    ``--yes`` runs it (the sweep itself replaced here: only the guard is under test)."""
    import slipmaps.runtime.sweep.run as sweep_run

    argv = ["sweep", "--map", "geyer", "--fixed", "apex_height=1.0", "--axis", "apex_speed=3:7:10000"]
    argv += ["--axis", "touchdown_angle=0.2:0.4:10000", "--out", str(tmp_path / "big")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "100,000,000 rows" in err and "GB of csv" in err and "--yes" in err
    assert not (tmp_path / "big").exists() or not any((tmp_path / "big").iterdir())
    ran = []

    def interrupted(*args, **kwargs):
        ran.append(args)
        raise KeyboardInterrupt

    monkeypatch.setattr(sweep_run, "sweep", interrupted)
    assert main([*argv, "--yes"]) == 130 and len(ran) == 1


# --- the scheduler's form, checked before it is tried (issue 52, item 3) ---------------------------


@pytest.mark.parametrize(
    "given",
    [
        "bogus:9",
        "host:8786",
        "tcp://host",
        "tcp://:8786",
        "tcp://host:0",
        "tcp://host:99999",
        "udp://host:1",
        "x",
    ],
)
def test_a_scheduler_in_no_documented_form_is_refused_before_it_is_tried(given, monkeypatch):
    """`--scheduler bogus:9` was tried as an address for 30 s; any string but the documented forms
    is one line naming them, and nothing connects."""
    import distributed
    from slipmaps.runtime.sweep.schedulers import check_scheduler

    monkeypatch.setattr(distributed, "Client", lambda *a, **k: pytest.fail("an address was tried"))
    with pytest.raises(ValueError) as info:
        check_scheduler(given)
    message = str(info.value)
    assert message == (
        "scheduler must be 'inprocess', 'local:N' (N workers on this machine) or a Dask scheduler's "
        f"address tcp://HOST:PORT, got {given!r}"
    )


@pytest.mark.parametrize(
    "given", ["inprocess", None, "local:2", "tcp://10.0.0.5:8786", "tls://host:8786", "tcp://[::1]:8786"]
)
def test_the_documented_scheduler_forms_pass_the_check(given):
    from slipmaps.runtime.sweep.schedulers import check_scheduler

    assert check_scheduler(given) == (None if given == "inprocess" else given)


def test_sweep_refuses_a_bogus_scheduler_naming_the_flag_exit_2(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["sweep", str(EXAMPLE), "--scheduler", "bogus:9", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert (
        err.startswith("slipmaps sweep: error: --scheduler must be 'inprocess', 'local:N'")
        and err.count("\n") == 1
    )
    assert "got 'bogus:9'" in err and not (out / "chunks").exists()


def test_reaching_a_scheduler_says_so_first(monkeypatch, capsys):
    """Reaching an address can take up to 30 s: a line on standard error says what is waited for."""
    import distributed
    from slipmaps.runtime.sweep import schedulers

    class Unreachable:
        def __init__(self, address, timeout):
            raise OSError(f"Timed out trying to connect to {address} after {timeout}")

    monkeypatch.setattr(distributed, "Client", Unreachable)
    with pytest.raises(ValueError, match="cannot reach the dask scheduler at tcp://10.0.0.5:8786"):
        with schedulers._client("tcp://10.0.0.5:8786"):
            pass
    err = capsys.readouterr().err
    wait = f"up to {schedulers.CONNECT_SECONDS} s"
    assert err == f"slipmaps: connecting to the Dask scheduler at tcp://10.0.0.5:8786 ({wait})\n"
