"""Where a sweep's chunks run: in this process (numba's threads), or on a Dask cluster.

A chunk task (:func:`chunk_file`) computes one chunk and encodes its file, so the process that
writes the files (this one) only stores bytes. Schedulers:

- ``None`` or ``"inprocess"``: one chunk after another here; each batch call is parallel over
  numba's threads;
- ``"local:N"``: a ``dask.distributed.LocalCluster`` of N worker processes on this machine (one dask
  thread each, numba threads = cores / N), started and closed by the sweep;
- a scheduler address (``"tcp://host:8786"``, ``tls://`` for TLS) or a ``distributed.Client``: an
  existing cluster. Its workers need slipmaps (and pyarrow for Parquet) installed; run them with
  ``--nthreads 1`` so that numba's threads have the cores.

Any other form is refused before anything is tried (:func:`check_scheduler`, one line naming the
forms). Reaching an address (up to :data:`CONNECT_SECONDS`) and starting a local cluster are a line
on standard error each (:func:`~slipmaps.runtime.api.notices.notice`).

On a cluster at most two tasks per worker thread are in flight (memory stays flat); results arrive
in any order, each written as it comes. A task whose worker dies is rerun by the scheduler; a task
that fails is resubmitted up to :data:`ATTEMPTS` times in all before the sweep stops with the error.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from ..api.notices import notice
from .compute import compute
from .files import encode
from .spec import Sweep

__all__ = ["ChunkFile", "chunk_file", "run_chunks", "ATTEMPTS", "CONNECT_SECONDS", "FORMS", "check_scheduler"]

#: Submissions of one chunk before a failure stops the sweep.
ATTEMPTS = 3
#: Seconds to reach a scheduler's address before the sweep stops with an error.
CONNECT_SECONDS = 30


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


#: The documented forms of a scheduler, as an error names them.
FORMS = "'inprocess', 'local:N' (N workers on this machine) or a Dask scheduler's address tcp://HOST:PORT"
#: The address schemes of a Dask scheduler (distributed's TCP and its TLS).
SCHEMES = ("tcp", "tls")


def _address_form(address: str) -> bool:
    """Whether ``address`` is ``tcp://HOST:PORT`` (or ``tls://``), the port 1-65535."""
    scheme, sep, rest = address.partition("://")
    host, colon, port = rest.rpartition(":")
    return (
        sep == "://"
        and scheme in SCHEMES
        and colon == ":"
        and bool(host.strip("[]"))
        and port.isdigit()
        and 0 < int(port) < 65536
    )


def check_scheduler(scheduler, what: str = "scheduler") -> object:
    """``scheduler`` if it is one of the documented forms (:data:`FORMS`; or a
    ``distributed.Client``) and, for Dask, dask.distributed is installed, checked without
    connecting; ValueError otherwise, one line naming ``what`` (the argument, the flag or the file's
    key) and the forms."""
    if scheduler is None or scheduler == "inprocess":
        return None
    if isinstance(scheduler, str):
        if scheduler.startswith("local:"):
            n = scheduler.partition(":")[2]
            if not n.isdigit() or int(n) < 1:
                raise ValueError(f"{what} 'local:N' needs a positive number of workers N, got {scheduler!r}")
        elif not _address_form(scheduler):
            raise ValueError(f"{what} must be {FORMS}, got {scheduler!r}")
    elif type(scheduler).__name__ != "Client":
        raise ValueError(f"{what} must be {FORMS} or a distributed.Client, got {type(scheduler).__name__}")
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise ValueError(
            "running a sweep on Dask needs dask.distributed: pip install 'slipmaps[dask]'"
        ) from None
    return scheduler


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
        notice(f"slipmaps: starting a local Dask cluster of {n} worker processes")
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
    notice(f"slipmaps: connecting to the Dask scheduler at {scheduler} (up to {CONNECT_SECONDS} s)")
    try:
        client = Client(scheduler, timeout=f"{CONNECT_SECONDS}s")
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
