"""One batch driver for every role kernel: rows in blocks, on threads when the batch is long.

Every generated role kernel has a batch form ``kernel_rows(X, P, OUT, STATUS)`` (derive/templates/
kernels.py.j2): a serial loop over the rows of ``X`` (``P`` one parameter record for every row, or
one per row) that releases the GIL. :func:`run_rows` calls it, and :func:`run_blocks` any compiled
loop over rows (the deadbeat solver's). The first batch of a kernel runs its first few rows in the
calling thread, timed: the cost of a row, remembered for the kernel's later batches. When the rows
would take long enough to pay for it, they are spread evenly over numba's thread count
(``numba.get_num_threads()``, set by ``NUMBA_NUM_THREADS``) in Python threads, the calling thread
running one block. A batch of up to :data:`PROBE` rows costs one call, about what a scalar call
costs; each row's result does not depend on how the rows were split.
"""

from __future__ import annotations

import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

__all__ = ["run_blocks", "run_rows"]

#: Rows run first, in the calling thread, to measure the cost of a row: few, since the threads
#: start after them (64 rows of the exact map's Jacobian, 1 ms, made a batch of 200 rows 1.3x as
#: long as an even split).
PROBE = 8
#: The rest goes to threads when it would take at least this long in one thread [s].
THREADED_SECONDS = 2e-4

#: Seconds per row of a kernel's batches (the first timed rows that did not compile it), by the
#: kernel (a numba dispatcher: its ``signatures`` tell a compilation).
_COST: dict = {}

_POOL: ThreadPoolExecutor | None = None
_POOL_SIZE = 0


def _threads() -> int:
    import numba

    return max(1, numba.get_num_threads())


def _pool(size: int) -> ThreadPoolExecutor:
    global _POOL, _POOL_SIZE
    if _POOL is None or _POOL_SIZE != size:
        if _POOL is not None:
            _POOL.shutdown(wait=False)
        _POOL, _POOL_SIZE = ThreadPoolExecutor(max_workers=size, thread_name_prefix="slipmaps"), size
    return _POOL


def run_blocks(block, n: int, key=None) -> None:
    """``block(lo, hi)`` over the rows 0..n in contiguous blocks (each releasing the GIL): the first
    :data:`PROBE` rows here and timed unless the cost of a row of ``key`` (the kernel; None: no
    memory) is known, the rest in even blocks on threads when that pays (module docstring)."""
    if n <= PROBE:  # one block, here: nothing to time
        if n:
            block(0, n)
        return
    first, per_row = 0, _COST.get(key) if key is not None else None
    if per_row is None:
        first = PROBE
        compiled = len(getattr(key, "signatures", ()))
        start = time.perf_counter()
        block(0, first)
        per_row = (time.perf_counter() - start) / first
        # remembered unless the kernel compiled (or loaded from numba's cache) in those rows
        if key is not None and len(getattr(key, "signatures", ())) == compiled:
            _COST[key] = per_row
    rest = n - first
    threads = min(_threads(), rest)
    if threads < 2 or per_row * rest < THREADED_SECONDS:
        block(first, n)
        return
    bounds = [first + rest * t // threads for t in range(threads + 1)]
    pool = _pool(threads - 1)
    jobs = [pool.submit(block, bounds[t], bounds[t + 1]) for t in range(1, threads)]
    block(bounds[0], bounds[1])  # one block here while the threads run the others
    for job in jobs:
        job.result()


def run_rows(rows, X: np.ndarray, P: np.ndarray, OUT: np.ndarray, STATUS: np.ndarray) -> None:
    """A role kernel's batch form ``rows(X, P, OUT, STATUS)`` over every row of ``X`` (C-contiguous
    float64, one row per call of the kernel; ``P`` (1, k) for one parameter record, (n, k) for one
    per row; ``OUT`` and ``STATUS`` one row each), by :func:`run_blocks`."""
    if X.shape[0] <= PROBE:  # one block (run_blocks would run it here too): no closure
        rows(X, P, OUT, STATUS)
        return
    shared = P.shape[0] == 1

    def block(lo, hi):
        rows(X[lo:hi], P if shared else P[lo:hi], OUT[lo:hi], STATUS[lo:hi])

    run_blocks(block, X.shape[0], rows)
