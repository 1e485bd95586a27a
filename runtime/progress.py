"""A minimal progress bar on standard error for long loops (exact batches, accuracy grids).

Shown when asked (``enabled=True``) or, with ``enabled=None``, when the loop is long and standard
error is a terminal; it never writes to standard output, so tables and JSON stay clean.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterable, Iterator
from typing import TypeVar

T = TypeVar("T")

#: With ``enabled=None`` the bar appears for loops of at least this many items.
AUTO_MIN_ITEMS = 200


def progress(items: Iterable[T], total: int, label: str, enabled: bool | None = None) -> Iterator[T]:
    """Yield ``items``, drawing ``label: i/total [elapsed < remaining]`` on stderr as it goes."""
    show = (total >= AUTO_MIN_ITEMS and sys.stderr.isatty()) if enabled is None else bool(enabled)
    if not show or total <= 0:
        yield from items
        return
    start = last = time.perf_counter()
    width = 24
    for i, item in enumerate(items, 1):
        yield item
        now = time.perf_counter()
        if now - last >= 0.1 or i == total:
            last = now
            done = int(width * i / total)
            rate = i / (now - start) if now > start else float("inf")
            eta = (total - i) / rate if rate > 0 else 0.0
            sys.stderr.write(
                f"\r{label}: [{'#' * done}{'.' * (width - done)}] {i}/{total} "
                f"{now - start:5.1f}s < {eta:5.1f}s "
            )
            sys.stderr.flush()
    sys.stderr.write("\n")
    sys.stderr.flush()
