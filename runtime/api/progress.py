"""Progress on standard error for long work: a minimal bar for long loops (exact batches, accuracy
grids, sweeps, the warm-up) and a line per stage of a command (:class:`Stages`). What numba
compiling a kernel says is :mod:`.notices`'s.

A bar is shown when asked (``enabled=True``) or, with ``enabled=None``, when the loop is long
(:func:`progress`: many items; :class:`Bar`: running for more than a second) and standard error is
a terminal; nothing here writes to standard output, so tables and JSON stay clean.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterable, Iterator
from typing import TypeVar

__all__ = ["AUTO_MIN_ITEMS", "Bar", "Stages", "clock", "is_terminal", "progress"]

T = TypeVar("T")

#: With ``enabled=None`` the bar appears for loops of at least this many items.
AUTO_MIN_ITEMS = 200


def progress(items: Iterable[T], total: int, label: str, enabled: bool | None = None) -> Iterator[T]:
    """Yield ``items``, drawing ``label: [###.....] i/total elapsed < remaining`` on stderr as it
    goes (a :class:`Bar` counting the items)."""
    show = (total >= AUTO_MIN_ITEMS and sys.stderr.isatty()) if enabled is None else bool(enabled)
    if not show or total <= 0:
        yield from items
        return
    with Bar(total, label, True) as bar:
        for item in items:
            yield item
            bar.update(1)


class Bar:
    """A progress bar updated by counts (``bar.update(n)``), for work done in uneven pieces (sweep
    chunks): ``label: [###.....] done/total unit  elapsed < remaining`` on standard error.

    ``enabled=None`` draws it only when standard error is a terminal and the work has already run
    for ``delay`` seconds (so short runs print nothing); ``True`` draws from the start, ``False``
    never. ``initial`` counts work done before (a resumed sweep); the rate and the remaining time
    are measured on the work done since the bar started. Use as a context manager, or call
    :meth:`close`.
    """

    WIDTH = 24

    def __init__(
        self,
        total: int,
        label: str,
        enabled: bool | None = None,
        *,
        initial: int = 0,
        unit: str = "",
        delay: float = 1.0,
    ) -> None:
        self.total = int(total)
        self.done = int(initial)
        self.label = label
        self.unit = f" {unit}" if unit else ""
        self._initial = int(initial)
        self._show = sys.stderr.isatty() if enabled is None else bool(enabled)
        self._delay = delay if enabled is None else 0.0
        self._start = self._last = time.perf_counter()
        self._drawn = False

    def update(self, n: int) -> None:
        self.done += int(n)
        now = time.perf_counter()
        if not self._show or now - self._start < self._delay:
            return
        if self._drawn and now - self._last < 0.1 and self.done < self.total:
            return
        self._last = now
        self._draw(now)

    def _draw(self, now: float) -> None:
        frac = min(1.0, self.done / self.total) if self.total > 0 else 1.0
        full = int(self.WIDTH * frac)
        elapsed = now - self._start
        new = self.done - self._initial
        eta = (self.total - self.done) * elapsed / new if new > 0 else float("inf")
        remaining = f"{eta:5.1f}s" if eta != float("inf") else "    ?s"  # nothing done yet: no rate
        sys.stderr.write(
            f"\r{self.label}: [{'#' * full}{'.' * (self.WIDTH - full)}] {self.done}/{self.total}{self.unit} "
            f"{elapsed:5.1f}s < {remaining} "
        )
        sys.stderr.flush()
        self._drawn = True

    def count(self, items: Iterable[T]) -> Iterator[T]:
        """Yield ``items``, each counted done after its turn; the bar closed after the last (or when
        the loop stops early)."""
        try:
            for item in items:
                yield item
                self.update(1)
        finally:
            self.close()

    def close(self) -> None:
        if self._drawn:
            self._draw(time.perf_counter())
            sys.stderr.write("\n")
            sys.stderr.flush()
            self._drawn = False

    def __enter__(self) -> Bar:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def is_terminal(stream) -> bool:
    """Whether ``stream`` is a terminal (False for a stream without ``isatty`` or a closed one)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False


class Stages:
    """A command's progress by stages on standard error: a line as each of its ``n`` stages starts,
    ``{command}: [i/n] what``, so a log holds one line per stage; on a terminal each line also
    gives the time since the command started, and :meth:`done` a last line with the total. The
    stages' own bars and the compile notices come between the lines on a terminal only."""

    def __init__(self, n: int, command: str) -> None:
        self.n = n
        self.command = command
        self.i = 0
        self.start = time.perf_counter()

    def __call__(self, what: str) -> None:
        self.i += 1
        line = f"{self.command}: [{self.i}/{self.n}] {what}"
        if is_terminal(sys.stderr):
            line += f" ({clock(time.perf_counter() - self.start)} so far)"
        print(line, file=sys.stderr, flush=True)

    def done(self) -> None:
        if is_terminal(sys.stderr):
            print(
                f"{self.command}: {self.n} stages in {clock(time.perf_counter() - self.start)}",
                file=sys.stderr,
                flush=True,
            )


def clock(seconds: float) -> str:
    """``12 s``, ``3 min 05 s``."""
    m, s = divmod(int(round(seconds)), 60)
    return f"{m} min {s:02d} s" if m else f"{s} s"
