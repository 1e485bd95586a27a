"""One batch driver for every role kernel: rows in blocks, on threads when the batch is long.

Every generated role kernel has a batch form ``kernel_rows(X, P, OUT, STATUS)`` (derive/templates/
kernels.py.j2): a serial loop over the rows of ``X`` (``P`` one parameter record for every row, or
one per row) that releases the GIL. :func:`run_rows` calls it, and :func:`run_blocks` any compiled
loop over rows (the deadbeat solver's), on the first block of rows in the calling thread and, when
the rest would take long enough to pay for it, spreads the rest over numba's thread count
(``numba.get_num_threads()``, set by ``NUMBA_NUM_THREADS``) in Python threads. A short batch
therefore costs one call, about what a scalar call costs; each row's result does not depend on how
the rows were split.
"""

from __future__ import annotations

import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

__all__ = ["run_blocks", "run_rows"]

#: Rows of the first block, run in the calling thread (it measures the cost of a row).
FIRST_BLOCK = 64
#: The rest goes to threads when it would take at least this long in one thread [s].
THREADED_SECONDS = 2e-4

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


def run_blocks(block, n: int) -> None:
    """``block(lo, hi)`` over the rows 0..n in contiguous blocks (each releasing the GIL): the first
    block here, the rest in blocks on threads when that pays (module docstring)."""
    if n <= FIRST_BLOCK:  # one block, here: nothing to time
        if n:
            block(0, n)
        return
    first = FIRST_BLOCK
    start = time.perf_counter()
    block(0, first)
    rest = n - first
    threads = min(_threads(), rest // FIRST_BLOCK)
    per_row = (time.perf_counter() - start) / first
    if threads < 2 or per_row * rest < THREADED_SECONDS:
        block(first, n)
        return
    bounds = np.linspace(first, n, threads + 1).astype(np.int64)
    blocks = list(zip(bounds[:-1].tolist(), bounds[1:].tolist(), strict=True))
    pool = _pool(threads - 1)
    jobs = [pool.submit(block, lo, hi) for lo, hi in blocks[1:]]
    block(*blocks[0])  # one block here while the threads run the others
    for job in jobs:
        job.result()


def run_rows(rows, X: np.ndarray, P: np.ndarray, OUT: np.ndarray, STATUS: np.ndarray) -> None:
    """A role kernel's batch form ``rows(X, P, OUT, STATUS)`` over every row of ``X`` (C-contiguous
    float64, one row per call of the kernel; ``P`` (1, k) for one parameter record, (n, k) for one
    per row; ``OUT`` and ``STATUS`` one row each), by :func:`run_blocks`."""
    if X.shape[0] <= FIRST_BLOCK:  # one block (run_blocks would run it here too): no closure
        rows(X, P, OUT, STATUS)
        return
    shared = P.shape[0] == 1

    def block(lo, hi):
        rows(X[lo:hi], P if shared else P[lo:hi], OUT[lo:hi], STATUS[lo:hi])

    run_blocks(block, X.shape[0])
