"""One batch driver for every role kernel: rows in blocks bounded in time, on threads when the batch
is long; Ctrl-C ends it within a fraction of a second, the rows finished kept.

Every generated role kernel has a batch form ``kernel_rows(X, P, OUT, STATUS)`` (derive/templates/
kernels.py.j2): a serial loop over the rows of ``X`` (``P`` one parameter record for every row, or
one per row) that releases the GIL. :func:`run_rows` calls it, and :func:`run_blocks` any compiled
loop over rows (the deadbeat solver's). The first batch of a kernel runs its first few rows in the
calling thread, timed: the cost of a row, remembered for the kernel's later batches. When the rows
would take long enough to pay for it, they run on numba's thread count (``numba.get_num_threads()``,
set by ``NUMBA_NUM_THREADS``) of Python threads. A batch of up to :data:`PROBE` rows costs one call,
about what a scalar call costs; each row's result does not depend on how the rows were split.

A compiled call cannot be interrupted: Python handles Ctrl-C when it returns. So no call runs for
long: a batch whose rows fit in one short block per thread (:data:`BLOCK_SECONDS`, at most
:data:`FIRST_BLOCK` rows each) is split evenly, the calling thread running one block; a longer one
is handed out in blocks of about :data:`BLOCK_SECONDS` each, sized by the cost of a row measured on
the blocks before (from at most :data:`FIRST_BLOCK` rows, growing at most :data:`GROWTH` times a
block, never more than an even share of the rows left), while the calling thread waits. Ctrl-C
raises :class:`BatchInterrupted` once the blocks running have finished: its ``done`` first rows
are finished, and the public batch functions put their result of those rows in its ``result``.
"""

from __future__ import annotations

import math
import threading
import time
from concurrent.futures import FIRST_EXCEPTION, ThreadPoolExecutor, wait

import numpy as np

__all__ = ["BatchInterrupted", "run_blocks", "run_rows"]

#: Rows run first, in the calling thread, to measure the cost of a row: few, since the threads
#: start after them (64 rows of the exact map's Jacobian, 1 ms, made a batch of 200 rows 1.3x as
#: long as an even split).
PROBE = 8
#: The rest goes to threads when it would take at least this long in one thread [s].
THREADED_SECONDS = 2e-4
#: A block of rows is sized to take about this long [s]: Ctrl-C waits for the blocks running.
BLOCK_SECONDS = 0.05
#: The rows of a first block per thread, at most: a row's cost measured on the first few rows can
#: be far below the others' (a batch that starts with invalid rows, which fail at once).
FIRST_BLOCK = 4096
#: A block has at most this many times the rows of the block before it.
GROWTH = 4
#: The shortest block worth handing out [s], however few rows are left (a block costs a few us).
MIN_BLOCK_SECONDS = 1e-3


class BatchInterrupted(KeyboardInterrupt):
    """Ctrl-C during a batch (a KeyboardInterrupt, so that code that stops on Ctrl-C stops on it):
    the first ``done`` of its ``total`` rows are finished (the rows in C order of the batch's
    shape), and ``result`` is what the public batch function returns, of those rows only (shape
    ``(done,)``): a :class:`~slipmaps.BatchResult`, :class:`~slipmaps.JacobianBatch` or
    :class:`~slipmaps.DeadbeatBatch` (from an internal call, its arrays of those rows, or None).

    ::

        try:
            res = slipmaps.apex_return_batch("exact", params, 1.0, 5.0, angles)
        except slipmaps.BatchInterrupted as stop:
            res = stop.result  # the rows finished before Ctrl-C: angles.ravel()[:stop.done]
    """

    def __init__(self, done: int, total: int, result=None):
        super().__init__(f"interrupted after {done:,} of {total:,} rows")
        self.done = int(done)
        self.total = int(total)
        self.result = result


#: Seconds per row of a kernel's batches (the first timed rows that did not compile it), by the
#: kernel (a numba dispatcher: its ``signatures`` tell a compilation).
_COST: dict = {}

_POOL: ThreadPoolExecutor | None = None
_POOL_SIZE = 0


def _threads() -> int:
    import numba

    return max(1, numba.get_num_threads())


def _pool(size: int) -> ThreadPoolExecutor:
    """The threads of the batches (``size`` of them, made again when the size changes)."""
    global _POOL, _POOL_SIZE
    if _POOL is None or _POOL_SIZE != size:
        if _POOL is not None:
            _POOL.shutdown(wait=False)
        _POOL, _POOL_SIZE = ThreadPoolExecutor(max_workers=size, thread_name_prefix="slipmaps"), size
    return _POOL


def run_blocks(block, n: int, key=None) -> None:
    """``block(lo, hi)`` over the rows 0..n in contiguous blocks (each releasing the GIL): the first
    :data:`PROBE` rows here and timed unless the cost of a row of ``key`` (the kernel; None: no
    memory) is known, the rest split evenly or handed out in blocks bounded in time, on threads
    when that pays (module docstring). Ctrl-C: :class:`BatchInterrupted` with the rows finished."""
    if n <= PROBE:  # one block, here: nothing to time
        if n:
            _here(block, 0, n, n)
        return
    first, per_row = 0, _COST.get(key) if key is not None else None
    if per_row is None:
        first = PROBE
        compiled = len(getattr(key, "signatures", ()))
        start = time.perf_counter()
        _here(block, 0, first, n)
        per_row = (time.perf_counter() - start) / first
        # remembered unless the kernel compiled (or loaded from numba's cache) in those rows
        if key is not None and len(getattr(key, "signatures", ())) == compiled:
            _COST[key] = per_row
    rest = n - first
    threads = min(_threads(), rest)
    if threads < 2 or per_row * rest < THREADED_SECONDS:
        threads = 1
    share = -(-rest // threads)  # the rows of an even split's block
    if share <= FIRST_BLOCK and per_row * share <= BLOCK_SECONDS:
        _split(block, first, n, threads)
        return
    blocks = _Blocks(block, first, n, per_row, threads)
    try:
        blocks.run(_pool(threads) if threads > 1 else None)
    except KeyboardInterrupt:
        raise BatchInterrupted(blocks.finished(), n) from None


def _here(block, lo: int, hi: int, n: int) -> None:
    """``block(lo, hi)`` in this thread; Ctrl-C: :class:`BatchInterrupted` with the rows before
    ``hi`` finished when Python handled it after the block (it cannot during a compiled call),
    else those before ``lo``."""
    ran = False
    try:
        block(lo, hi)
        ran = True
    except KeyboardInterrupt:
        raise BatchInterrupted(hi if ran else lo, n) from None


def _split(block, first: int, n: int, threads: int) -> None:
    """The rows first..n in ``threads`` even blocks, one here while the threads run the others."""
    if threads < 2:
        _here(block, first, n, n)
        return
    bounds = [first + (n - first) * t // threads for t in range(threads + 1)]
    pool = _pool(threads)
    jobs = [pool.submit(block, bounds[t], bounds[t + 1]) for t in range(1, threads)]
    try:
        _here(block, bounds[0], bounds[1], n)
        for job in jobs:
            job.result()
    except KeyboardInterrupt as stop:
        wait(jobs)  # short blocks (the reason for an even split)
        done = stop.done if isinstance(stop, BatchInterrupted) else bounds[1]
        raise BatchInterrupted(n if done == bounds[1] else first, n) from None


class _Blocks:
    """The rows lo..n handed out in blocks bounded in time (module docstring) to the threads that
    call :meth:`work`; :meth:`finished` the rows finished from row 0 on."""

    def __init__(self, block, lo: int, n: int, per_row: float, threads: int):
        self.block = block
        self.start = lo
        self.next = lo
        self.n = n
        self.per_row = per_row
        self.threads = threads
        self.rows = FIRST_BLOCK // GROWTH  # the rows of the block before
        self.stop = False
        self.done: list[tuple[int, int]] = []
        self.lock = threading.Lock()

    def take(self) -> tuple[int, int] | None:
        """The next block (None when none is left or the batch stops): about
        :data:`BLOCK_SECONDS` at the last block's cost of a row, at most :data:`GROWTH` times the
        block before, at most an even share of the rows left unless that is shorter than
        :data:`MIN_BLOCK_SECONDS`."""
        with self.lock:
            left = self.n - self.next
            if self.stop or left <= 0:
                return None
            per_row = self.per_row if self.per_row > 0 else 0.0
            timed = BLOCK_SECONDS / per_row if per_row else math.inf
            shortest = MIN_BLOCK_SECONDS / per_row if per_row else math.inf
            size = min(GROWTH * self.rows, timed, max(-(-left // self.threads), shortest))
            size = int(min(left, max(1, size)))
            lo = self.next
            self.next += size
            self.rows = size
            return lo, lo + size

    def work(self) -> None:
        """Run blocks until none is left (in one thread; each block timed for the next's size)."""
        while (span := self.take()) is not None:
            start = time.perf_counter()
            self.block(*span)
            seconds = time.perf_counter() - start
            with self.lock:
                self.done.append(span)
                if seconds > 0:
                    self.per_row = seconds / (span[1] - span[0])

    def run(self, pool: ThreadPoolExecutor | None) -> None:
        """Every block: here when ``pool`` is None (Ctrl-C between two blocks), else on the pool's
        threads while this one waits (Ctrl-C stops the handing out; the blocks running finish)."""
        if pool is None:
            self.work()
            return
        jobs = [pool.submit(self.work) for _ in range(self.threads)]
        try:
            while wait(jobs, timeout=0.25, return_when=FIRST_EXCEPTION).not_done:
                for job in jobs:
                    if job.done() and job.exception() is not None:
                        raise job.exception()
            for job in jobs:
                job.result()
        except BaseException:
            self.stop = True
            wait(jobs)
            raise

    def finished(self) -> int:
        """The rows finished without a gap from row 0 (a block taken but not run ends them)."""
        end = self.start
        for lo, hi in sorted(self.done):
            if lo != end:
                break
            end = hi
        return end


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
