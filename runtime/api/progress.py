"""Progress on standard error for long work: a minimal bar for long loops (exact batches, accuracy
grids, sweeps) and a line while numba compiles a kernel (:func:`compile_notices`).

A bar is shown when asked (``enabled=True``) or, with ``enabled=None``, when the loop is long
(:func:`progress`: many items; :class:`Bar`: running for more than a second) and standard error is
a terminal; nothing here writes to standard output, so tables and JSON stay clean.
"""

from __future__ import annotations

import contextlib
import sys
import threading
import time
from collections.abc import Iterable, Iterator
from typing import TypeVar

from numba.core import event

__all__ = [
    "AUTO_MIN_ITEMS",
    "NOTICE_DELAY",
    "Bar",
    "CompileNotices",
    "compile_notices",
    "compiling_what",
    "is_terminal",
    "progress",
]

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
        sys.stderr.write(
            f"\r{self.label}: [{'#' * full}{'.' * (self.WIDTH - full)}] {self.done}/{self.total}{self.unit} "
            f"{elapsed:5.1f}s < {eta:5.1f}s "
        )
        sys.stderr.flush()
        self._drawn = True

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


#: What a compiled function is, by its module, in a compile notice (else the module and the name).
_WHAT = {"slipmaps.runtime.control.compiled": "the deadbeat solver"}


def compiling_what(dispatcher) -> str:
    """A compile notice's name of what numba compiles: a generated kernel by its name and file
    (``iterative_apex_return_rows of generated/iterative.py``), a runtime kernel by its role."""
    func = getattr(dispatcher, "py_func", None)
    module = getattr(func, "__module__", "") or ""
    name = getattr(func, "__name__", None) or str(dispatcher)
    if module.startswith("slipmaps.generated."):
        return f"{name} of generated/{module.rsplit('.', 1)[1]}.py"
    if module in _WHAT:
        return f"{_WHAT[module]}'s {name}"
    return f"{module}.{name}" if module else name


class CompileNotices(event.Listener):
    """A listener of numba's ``numba:compile`` event (numba.core.event), which numba fires only when
    it compiles a function, never when it loads one from its cache: so a notice appears exactly on
    a first use with an empty or stale cache (or for a function numba does not cache). For each
    outermost compile (the kernels it calls are compiled inside it) still running after ``delay``
    seconds, one line on ``stream``, ``slipmaps: compiling NAME (first use; cached for the next
    runs) ... 12 s``, its seconds counted every ``tick`` seconds in place and its time written
    when it ends. Install it with :func:`compile_notices`."""

    def __init__(self, stream, delay: float = 1.0, tick: float = 1.0) -> None:
        self.stream = stream
        self.delay = delay
        self.tick = tick
        self._depth = 0
        self._line = ""
        self._start = 0.0
        self._drawn = False
        self._stop: threading.Event | None = None
        self._thread: threading.Thread | None = None

    # numba calls these under its compiler lock: one compile at a time, whatever the thread
    def on_start(self, ev) -> None:
        self._depth += 1
        if self._depth > 1:
            return
        dispatcher = (ev.data or {}).get("dispatcher")
        cached = type(getattr(dispatcher, "_cache", None)).__name__ not in ("NullCache", "NoneType")
        when = "first use; cached for the next runs" if cached else "once per process"
        self._line = f"slipmaps: compiling {compiling_what(dispatcher)} ({when}) ..."
        self._start = time.perf_counter()
        self._drawn = False
        if self.delay <= 0:
            self._draw()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._ticks, name="slipmaps-compile-notice", daemon=True)
        self._thread.start()

    def _ticks(self) -> None:
        stop = self._stop
        if stop.wait(self.delay if not self._drawn else self.tick):
            return
        while True:
            self._draw()
            if stop.wait(self.tick):
                return

    def _draw(self, end: str = "") -> None:
        elapsed = time.perf_counter() - self._start
        seconds = f"{elapsed:.1f} s" if end else f"{elapsed:.0f} s"
        self.stream.write(f"\r{self._line} {seconds}{end}")
        self.stream.flush()
        self._drawn = True

    def on_end(self, ev) -> None:
        self._depth = max(0, self._depth - 1)
        if self._depth:
            return
        if self._stop is not None:
            self._stop.set()
            self._thread.join()
            self._stop = self._thread = None
        if self._drawn:
            self._draw("\n")
            self._drawn = False


#: A compile shorter than this [s] shows no line (:func:`compile_notices`).
NOTICE_DELAY = 1.0


def compile_notices(stream=None, enabled: bool | None = None, delay: float | None = None):
    """A context in which every numba compile that takes more than ``delay`` seconds (default
    :data:`NOTICE_DELAY`) is a line on ``stream`` (default standard error; :class:`CompileNotices`):
    with ``enabled=None`` only when ``stream`` is a terminal (nothing when it is piped or
    redirected), ``False`` never. The command line runs every command in one (runtime/cli/app.py)."""
    stream = sys.stderr if stream is None else stream
    show = is_terminal(stream) if enabled is None else bool(enabled)
    if not show:
        return contextlib.nullcontext()
    listener = CompileNotices(stream, NOTICE_DELAY if delay is None else delay)
    return event.install_listener("numba:compile", listener)
