"""Where a sweep's chunks run: in this process (numba's threads), or on a Dask cluster.

A chunk task (:func:`chunk_file`) computes one chunk and encodes its file, so the process that
writes the files (this one) only stores bytes. Schedulers:

- ``None`` or ``"inprocess"``: one chunk after another here; each batch call is parallel over
  numba's threads;
- ``"local:N"``: a ``dask.distributed.LocalCluster`` of N worker processes on this machine (one dask
  thread each, numba threads = cores / N), started and closed by the sweep;
- a scheduler address (``"tcp://host:8786"``) or a ``distributed.Client``: an existing cluster. Its
  workers need slipmaps (and pyarrow for Parquet) installed; run them with ``--nthreads 1`` so that
  numba's threads have the cores.

On a cluster at most two tasks per worker thread are in flight (memory stays flat); results arrive
in any order, each written as it comes. A task whose worker dies is rerun by the scheduler; a task
that fails is resubmitted up to :data:`ATTEMPTS` times in all before the sweep stops with the error.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from .compute import compute
from .files import encode
from .spec import Sweep

__all__ = ["ChunkFile", "chunk_file", "run_chunks", "ATTEMPTS", "check_scheduler"]

#: Submissions of one chunk before a failure stops the sweep.
ATTEMPTS = 3


@dataclass(frozen=True)
class ChunkFile:
    """One computed chunk, encoded: what a task returns."""

    index: int
    rows: int
    counts: dict[str, int]
    payload: bytes


def chunk_file(sweep: Sweep, fmt: str, digest: str, index: int, threads: int | None = None) -> ChunkFile:
    """Compute chunk ``index`` and encode its file (the task a worker runs); ``threads``: numba's
    thread count for this call."""
    if threads is not None:
        import numba

        numba.set_num_threads(max(1, min(threads, numba.config.NUMBA_NUM_THREADS)))
    chunk = compute(sweep, index)
    return ChunkFile(index, chunk.rows, chunk.counts(), encode(sweep, fmt, digest, chunk))


def check_scheduler(scheduler) -> object:
    """``scheduler`` if it names a scheduler and, for Dask, dask.distributed is installed (without
    connecting); ValueError otherwise."""
    if scheduler is None or scheduler == "inprocess":
        return None
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise ValueError(
            "running a sweep on Dask needs dask.distributed: pip install 'slipmaps[dask]'"
        ) from None
    if isinstance(scheduler, str):
        if scheduler.startswith("local:"):
            n = scheduler.partition(":")[2]
            if not n.isdigit() or int(n) < 1:
                raise ValueError(f"scheduler 'local:N' needs a positive number of workers, got {scheduler!r}")
            return scheduler
        if "://" in scheduler or ":" in scheduler:
            return scheduler
        raise ValueError(
            "scheduler must be 'inprocess', 'local:N' or a dask scheduler address (tcp://host:8786), "
            f"got {scheduler!r}"
        )
    if type(scheduler).__name__ == "Client":
        return scheduler
    raise ValueError(f"scheduler must be a string or a distributed.Client, got {type(scheduler).__name__}")


def run_chunks(
    sweep: Sweep, fmt: str, digest: str, indices: Iterable[int], scheduler=None
) -> Iterator[ChunkFile]:
    """The chunks ``indices`` of ``sweep``, computed where ``scheduler`` says, as they complete."""
    scheduler = check_scheduler(scheduler)
    if scheduler is None:
        for i in indices:
            yield chunk_file(sweep, fmt, digest, i)
        return
    with _client(scheduler) as (client, threads):
        yield from _on_dask(client, threads, sweep, fmt, digest, indices)


@contextmanager
def _client(scheduler):
    """(client, numba threads per task) for ``scheduler``; a local cluster is closed afterwards."""
    from distributed import Client, LocalCluster

    if isinstance(scheduler, Client):
        yield scheduler, None
        return
    if scheduler.startswith("local:"):
        n = int(scheduler.partition(":")[2])
        cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
        cluster = LocalCluster(
            n_workers=n, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
        )
        try:
            with Client(cluster) as client:
                yield client, max(1, cores // n)
        finally:
            cluster.close()
        return
    try:
        client = Client(scheduler, timeout="30s")
    except OSError as exc:
        raise ValueError(f"cannot reach the dask scheduler at {scheduler}: {exc}") from None
    with client:
        yield client, None


def _on_dask(
    client, threads, sweep: Sweep, fmt: str, digest: str, indices: Iterable[int]
) -> Iterator[ChunkFile]:
    from distributed import as_completed

    pending = iter(indices)
    attempts: dict[int, int] = {}
    window = max(2, 2 * sum(client.nthreads().values()))
    running = as_completed()
    which = {}

    def submit(i: int) -> None:
        attempts[i] = attempts.get(i, 0) + 1
        key = f"slipmaps-sweep-{digest[:12]}-{i}-{attempts[i]}"
        fut = client.submit(chunk_file, sweep, fmt, digest, i, threads, key=key, pure=False, retries=1)
        which[fut.key] = i
        running.add(fut)

    for i in pending:
        submit(i)
        if running.count() >= window:
            break
    for fut in running:
        i = which.pop(fut.key)
        try:
            result = fut.result()
        except Exception as exc:
            if attempts[i] >= ATTEMPTS:
                raise RuntimeError(
                    f"sweep chunk {i} failed {attempts[i]} times; last error: {exc!r}"
                ) from exc
            submit(i)
            continue
        finally:
            fut.release()
        yield result
        nxt = next(pending, None)
        if nxt is not None:
            submit(nxt)
