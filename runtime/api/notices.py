"""What slipmaps says on standard error while a user waits: a kernel compiling on its first call,
a Dask scheduler being reached.

numba compiles a kernel on its first call (seconds to tens of seconds) and caches it on disk, so
later processes load it. A compile of slipmaps' own code that lasts more than :data:`NOTICE_DELAY`
seconds is one line on standard error, from the Python API as from the command line::

    compiling slipmaps' iterative apex_return_jacobian (first call; cached afterwards) ...

naming the map and the role (the API call: ``apex_return_jacobian``; ``, batch`` for a batch's
kernel). numba fires its ``numba:compile`` event (numba.core.event) only when it compiles, never
when it loads a kernel from its cache (``Dispatcher.compile`` looks in the cache first): so a line
appears exactly on a first call with an empty or stale cache, and for what numba cannot cache
(``first call in this process``). On a terminal the line counts the seconds in place and ends with
the time the compile took; elsewhere (a file, a pipe, a notebook) it is written once, as is.

Silence them with ``slipmaps.notices(False)`` (:func:`notices`), or the environment variable
``SLIPMAPS_NOTICES=0`` (:data:`NOTICES_ENV`) before slipmaps runs; ``notices(None)`` shows
them on a terminal only. The command line shows them on a terminal only, none with
``--no-progress`` (:func:`compile_notices`). ``slipmaps warmup`` compiles every kernel ahead, on
every core (``slipmaps.runtime.control.warmup``).
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
import time
from functools import cache

from numba.core import event

from .progress import is_terminal

__all__ = [
    "NOTICES_ENV",
    "NOTICE_DELAY",
    "CompileNotices",
    "compile_notices",
    "compiling_what",
    "install",
    "notice",
    "notices",
]

#: The environment variable of the notices' default: ``0`` none, ``terminal`` on a terminal only,
#: anything else (or unset) always.
NOTICES_ENV = "SLIPMAPS_NOTICES"
#: A compile shorter than this [s] shows no line.
NOTICE_DELAY = 1.0


def _from_environment() -> bool | None:
    value = os.environ.get(NOTICES_ENV, "").strip().lower()
    return False if value in ("0", "false", "no", "off") else None if value == "terminal" else True


def _shown(enabled: bool | None, stream) -> bool:
    return is_terminal(stream) if enabled is None else bool(enabled)


#: What a compiled function of slipmaps' runtime is, by its module, in a notice.
_WHAT = {
    "slipmaps.runtime.control.compiled": "deadbeat solver",
    "slipmaps.runtime.control.footholds_solver": "footholds planner",
}


@cache
def _roles() -> dict[tuple[str, str], str]:
    """(generated module, function name) -> what it is: a map's role kernel (``iterative
    apex_return``; with an option's other choice ``iterative stance (geyer)``), its batch form
    (``, batch``), a model kernel (``model apex_to_touchdown``); from the index."""
    from . import index

    out: dict[tuple[str, str], str] = {}
    for m in (*index.maps(), *index.halves()):
        choices = {suffix: choice for choice, suffix in m.choices.items()}
        for role, spec in m.kernels.items():
            named = {spec.name: f"{m.name} {role}"}
            for suffix, choice in choices.items():
                other = spec.chosen(suffix)
                if other.name != spec.name:
                    named.setdefault(other.name, f"{m.name} {role} ({choice})")
            for name, what in named.items():
                out.setdefault((spec.module, name), what)
                out.setdefault((spec.module, f"{name}_rows"), f"{what}, batch")
    for name, spec in index.model_kernels().items():
        out.setdefault((spec.module, spec.name), f"model {name}")
        out.setdefault((spec.module, f"{spec.name}_rows"), f"model {name}, batch")
    return out


def compiling_what(dispatcher) -> str:
    """A notice's name of what numba compiles: a map's role kernel by map and role (``slipmaps'
    iterative apex_return_jacobian``), another generated kernel by its name and file, a runtime
    kernel by its job (``slipmaps' deadbeat solver (solve_rows)``)."""
    func = getattr(dispatcher, "py_func", None)
    module = getattr(func, "__module__", "") or ""
    name = getattr(func, "__name__", None) or str(dispatcher)
    if module.startswith("slipmaps.generated."):
        file = module.rsplit(".", 1)[1]
        try:
            role = _roles().get((file, name))
        except Exception:  # an index that cannot be read: the kernel's own name
            role = None
        return f"slipmaps' {role}" if role else f"slipmaps' {name} of generated/{file}.py"
    if module in _WHAT:
        return f"slipmaps' {_WHAT[module]} ({name})"
    return f"slipmaps' {module.removeprefix('slipmaps.')}.{name}" if module else name


def _slipmaps(dispatcher) -> bool:
    """Whether ``dispatcher`` compiles slipmaps' own code (other numba code in the process is not
    slipmaps' to announce)."""
    module = getattr(getattr(dispatcher, "py_func", None), "__module__", "") or ""
    return module == "slipmaps" or module.startswith("slipmaps.")


class CompileNotices(event.Listener):
    """A listener of numba's ``numba:compile`` event (module docstring): for each outermost compile
    of slipmaps' code (the kernels it calls compile inside it) still running after ``delay``
    seconds (default :data:`NOTICE_DELAY`), one line on ``stream`` (default: standard error at the
    time), when ``enabled`` (True always, None on a terminal only, False never): on a terminal its
    seconds counted every ``tick`` seconds in place and its time written when it ends. One is
    registered for the process (:func:`install`); :func:`notices` and :func:`compile_notices`
    change its settings."""

    def __init__(
        self, stream=None, enabled: bool | None = True, delay: float | None = None, tick: float = 1.0
    ):
        self.stream = stream
        self.enabled = enabled
        self.delay = delay
        self.tick = tick
        self._depth = 0
        self._line = ""
        self._out = None
        self._live = False  # a terminal: the line redrawn in place
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
        out = sys.stderr if self.stream is None else self.stream
        if out is None or not _slipmaps(dispatcher) or not _shown(self.enabled, out):
            self._out = None
            return
        cached = type(getattr(dispatcher, "_cache", None)).__name__ not in ("NullCache", "NoneType")
        when = "first call; cached afterwards" if cached else "first call in this process"
        self._line = f"compiling {compiling_what(dispatcher)} ({when}) ..."
        self._out = out
        self._live = is_terminal(out)
        self._start = time.perf_counter()
        self._drawn = False
        delay = NOTICE_DELAY if self.delay is None else self.delay
        if delay <= 0:
            self._draw()
            if not self._live:
                return
        self._stop = threading.Event()
        self._thread = threading.Thread(
            target=self._ticks, args=(delay,), name="slipmaps-compile-notice", daemon=True
        )
        self._thread.start()

    def _ticks(self, delay: float) -> None:
        stop = self._stop
        if not self._drawn and stop.wait(delay):
            return
        while True:
            if self._live or not self._drawn:
                self._draw()
            if not self._live or stop.wait(self.tick):
                return

    def _draw(self, end: str = "") -> None:
        try:
            if not self._live:  # once, as it is: no seconds to count in a file or a pipe
                self._out.write(f"{self._line}\n")
            else:
                elapsed = time.perf_counter() - self._start
                seconds = f"{elapsed:.1f} s" if end else f"{elapsed:.0f} s"
                self._out.write(f"\r{self._line} {seconds}{end}")
            self._out.flush()
        except (OSError, ValueError):  # a closed stream: nothing to say
            pass
        self._drawn = True

    def on_end(self, ev) -> None:
        self._depth = max(0, self._depth - 1)
        if self._depth:
            return
        if self._stop is not None:
            self._stop.set()
            self._thread.join()
            self._stop = self._thread = None
        if self._drawn and self._live:
            self._draw("\n")
        self._drawn = False
        self._out = None


#: The process's listener (:func:`install`).
NOTICES = CompileNotices(enabled=_from_environment())
_installed = False


def install() -> None:
    """Register :data:`NOTICES` with numba, once (importing ``slipmaps.runtime`` does: any public
    name but ``Status`` and ``MESSAGES``)."""
    global _installed
    if not _installed:
        event.register("numba:compile", NOTICES)
        _installed = True


def notices(enabled: bool | None) -> bool | None:
    """Whether slipmaps says on standard error what it does while a user waits (a kernel compiling
    on its first call, a Dask scheduler being reached; module docstring): True always (the default),
    None on a terminal only, False never. Returns the setting before. The environment variable
    ``SLIPMAPS_NOTICES=0`` sets False before slipmaps is imported (``terminal``: None)."""
    if enabled not in (True, False, None):
        raise ValueError(f"notices takes True, False or None (on a terminal only), got {enabled!r}")
    before, NOTICES.enabled = NOTICES.enabled, enabled
    return before


@contextlib.contextmanager
def compile_notices(stream=None, enabled: bool | None = None, delay: float | None = None):
    """A context in which the notices go to ``stream`` (default standard error) when ``enabled``
    (None: on a terminal only; False never) after ``delay`` seconds (default
    :data:`NOTICE_DELAY`): the command line runs every command in one (runtime/cli/app.py), off
    with ``--no-progress``. Silenced notices (:func:`notices`, ``SLIPMAPS_NOTICES=0``) stay silent."""
    install()
    saved = NOTICES.stream, NOTICES.enabled, NOTICES.delay
    NOTICES.stream, NOTICES.delay = stream, delay
    NOTICES.enabled = False if saved[1] is False else enabled
    try:
        yield NOTICES
    finally:
        NOTICES.stream, NOTICES.enabled, NOTICES.delay = saved


def notice(text: str) -> None:
    """``text`` as one line on standard error when notices are shown there (:func:`notices`): what a
    wait that is not a compile is (a Dask scheduler being reached)."""
    out = sys.stderr if NOTICES.stream is None else NOTICES.stream
    if out is not None and _shown(NOTICES.enabled, out):
        print(text, file=out, flush=True)
