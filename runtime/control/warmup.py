"""Compile slipmaps' kernels into numba's disk cache ahead, on every core: ``slipmaps warmup [MAPS]``.

numba compiles a kernel on its first call (seconds to a minute each on an empty cache) and caches
it on disk. :func:`warm` finds the jobs (:func:`jobs`) with a kernel that has no entry in numba's
cache for the types the API calls it with (:func:`cold_jobs`), and runs those in ``processes``
subprocesses that take the jobs one at a time, longest first (an estimate: :func:`_order`), as
they finish: the jobs of the modules' role kernels first, then, once those have finished, the jobs
of single kernels that call them (:class:`Phases`); a progress bar on a terminal counts them. With
a warm cache it imports the generated modules and reads their cache indexes: no subprocess. The
command line's ``slipmaps warmup`` and the test suite's warm-up (tests/warmup.py, which adds the
kernels only tests call) are this module.

A job is a generated module's role kernels at the maps' default options (every role of every map
and half-stance map, and the model's kernels: the index, ``runtime/api/index.py``), one kernel
(``module:function``: every map's Jacobians' batch forms), or the deadbeat solver and the
footholds' least squares (:data:`CONTROL`, runtime/control/compiled.py, footholds_solver.py).
``maps`` narrows them to those maps' kernels (no model kernels, no solver).

numba keys a cache entry by the exact signature a compile asks for. A kernel is compiled
(``dispatcher.compile``, not run) for the types every caller passes (C-contiguous float64,
writable; int64 statuses; float64 scalars), so the entry is the one a call looks up; a kernel the
deadbeat solver binds as a first-class function is looked up by its full signature, int64 return
type included (``MODEL`` of runtime/control/compiled.py), a second entry the warm-up saves too.
What no entry can serve, every process that needs it compiles: the solver bound to a map's kernels
(``compiled.bind``: a closure over two dispatchers, whose key pickles them with an identity of
their process).

The subprocesses are a plain ``python -m slipmaps.runtime.control.warmup --worker [MAPS]`` (or
the command a caller gives: the suite's own jobs) reading job names on standard input, with
slipmaps' compile notices off (``SLIPMAPS_NOTICES=0``), so a failure there only leaves work to
later calls, as without the warm-up.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from ..api.notices import NOTICES_ENV
from ..api.progress import Bar

__all__ = [
    "CONTROL",
    "Phases",
    "Warmed",
    "cold_jobs",
    "cores",
    "compile_job",
    "jobs",
    "role_specs",
    "signatures",
    "solver_signature",
    "warm",
    "worker",
]

#: The job that compiles the deadbeat solver's and the footholds' cached kernels
#: (runtime/control/compiled.py, footholds_solver.py: they compile when imported), not a generated
#: module.
CONTROL = "control"
#: Roles the deadbeat solver binds as first-class functions (runtime/control: deadbeat.py, bottom.py).
SOLVER_ROLES = ("apex_return", "apex_return_jacobian", "apex")
#: Roles whose batch form is its own job (a ``module:function`` job, after the modules' jobs).
JACOBIAN_ROLES = ("stance_jacobian", "apex_return_jacobian")

#: A job's work: ``(function, argument types, bound)`` to compile, ``bound`` True for a kernel the
#: deadbeat solver binds (:func:`solver_signature`).
Work = list[tuple]


def _selected(maps) -> tuple:
    """The maps and half-stance maps named in ``maps`` (None: all); ValueError naming one unknown
    and the valid names."""
    from ..api import index

    every = (*index.maps(), *index.halves())
    if maps is None:
        return every
    by_name = {m.name: m for m in every}
    for name in maps:
        if name not in by_name:
            raise ValueError(
                f"unknown map {name!r}; the maps are {', '.join(index.names())}, the half-stance "
                f"maps {', '.join(h.name for h in index.halves())}"
            )
    return tuple(by_name[name] for name in dict.fromkeys(maps))


def role_specs(maps=None) -> dict[str, list]:
    """Every role kernel's spec (:class:`~slipmaps.runtime.api.index.KernelSpec`) at the maps'
    default options, by generated module, of the maps named in ``maps`` (None: every map and
    half-stance map, and the model's kernels)."""
    from ..api import index

    by_module: dict[str, dict] = {}
    for m in _selected(maps):
        for s in m.kernels.values():  # at the map's default options (a specialized one's default choice)
            by_module.setdefault(s.module, {})[s.name] = s
    if maps is None:
        for s in index.model_kernels().values():
            by_module.setdefault(s.module, {})[s.name] = s
    return {module: list(specs.values()) for module, specs in sorted(by_module.items())}


def signatures(spec, row: bool = True, rows: bool | None = None) -> list[tuple]:
    """``(function, argument types)`` the warm-up compiles for ``spec``: the role kernel at the types
    of ``kernel(x, p, out)`` (unless ``row`` is False), and its batch form at those of
    ``kernel_rows(X, P, OUT, STATUS)`` (C-contiguous float64, writable; int64 statuses) when
    ``rows``, by default unless it is a Jacobian's (its batch form is a job of its own)."""
    import numba
    import numpy as np

    kernel, batch = spec.functions()
    nx, np_, width = len(spec.x), max(1, len(spec.p)), spec.width
    out = [(kernel, (np.empty(nx), np.empty(np_), np.empty(width)))] if row else []
    if rows if rows is not None else not spec.wrt:
        args = (np.empty((1, nx)), np.empty((1, np_)), np.empty((1, width)), np.empty(1, np.int64))
        out.append((batch, args))
    return [(f, tuple(map(numba.typeof, args))) for f, args in out]


@cache
def _jobs(maps: tuple[str, ...] | None) -> dict[str, Work]:
    selected = _selected(maps)
    bound = {(s.module, s.name) for m in selected for role, s in m.kernels.items() if role in SOLVER_ROLES}
    out: dict[str, Work] = {}
    for module, specs in role_specs(maps).items():
        out[module] = [
            (f, types, (s.module, s.name) in bound and f is s.functions()[0])
            for s in specs
            for f, types in signatures(s)
        ]
    for m in selected:  # every map's Jacobians' batch forms: a job each, after the modules'
        for role in JACOBIAN_ROLES:
            spec = m.kernels.get(role)
            if spec is not None:
                out[f"{spec.module}:{spec.name}_rows"] = [
                    (f, types, False) for f, types in signatures(spec, row=False, rows=True)
                ]
    return out


def jobs(maps=None) -> dict[str, Work]:
    """Every job of the maps named in ``maps`` (None: all, and the model's kernels) but
    :data:`CONTROL`: a generated module's role kernels at the defaults (:func:`role_specs`) by the
    module's name, and each Jacobian's batch form as ``module:function``."""
    return _jobs(None if maps is None else tuple(maps))


def solver_signature(types: tuple):
    """How the deadbeat solver's binding (runtime/control/compiled.py, ``bind``: a kernel as a
    first-class function of type ``MODEL``) compiles, and looks up in the cache, a role kernel of
    argument types ``types``: with its int64 return type, another cache entry than a call's."""
    import numba

    return numba.types.int64(*types)


def _cached(dispatcher, key) -> bool:
    """Whether numba's cache holds an entry of ``dispatcher`` for ``key`` (argument types, or a full
    signature) and its source as it is now (numba's own check: the index's stamp against the
    file's); True when that cannot be read."""
    try:
        return any(k[0] == key for k in dispatcher._cache._cache_file._load_index())
    except Exception:  # numba's internals moved: assume warm, the calls compile what is missing
        return True


def _keys(types: tuple, bound: bool) -> list:
    return [types, solver_signature(types)] if bound else [types]


def _generated_file(module: str) -> Path:
    import slipmaps.generated

    return Path(slipmaps.generated.__file__).parent / f"{module}.py"


def _order(job: str, table: Mapping[str, Work]) -> tuple:
    """The estimated longest jobs first: those of the exact simulator's modules (generated/
    exact_stance.py and the modules that import it: their kernels inline its DOP853 integrator,
    the longest compiles), then by the size of the job's module; a module's jobs in the order of
    ``table``."""
    module = job.split(":")[0]
    text = _generated_file(module).read_text()
    head = text.split('"""', 1)[0]  # the header's "Depends on" list names the modules it imports
    exact = module == "exact_stance" or "exact_stance.py" in head
    return (not exact, -len(text), list(table).index(job))


def cold_jobs(table: Mapping[str, Work] | None = None, control: bool = True) -> list[str]:
    """The jobs of ``table`` (default: :func:`jobs`) with a kernel missing from numba's cache,
    longest first (:func:`_order`), after :data:`CONTROL` (when ``control``) when any is cold."""
    table = jobs() if table is None else table
    cold = [
        job
        for job, work in table.items()
        if not all(_cached(f, key) for f, types, bound in work for key in _keys(types, bound))
    ]
    cold.sort(key=lambda job: _order(job, table))
    return [CONTROL, *cold] if cold and control else cold  # the solver: about a minute, so first


def _compile(function, types: tuple, bound: bool) -> None:
    """Compile ``function`` for ``types`` into the cache (what a call with those types compiles,
    without running it), and for a kernel the solver binds under its :func:`solver_signature` too."""
    function.compile(types)
    if not bound or _cached(function, solver_signature(types)):
        return
    try:  # the same machine code under the solver's key, without compiling it again
        function._cache.save_overload(solver_signature(types), function.overloads[types])
    except Exception:  # loaded from the cache (numba cannot save that again): compile it afresh
        fresh = type(function)(function.py_func, locals=function.locals, targetoptions=function.targetoptions)
        fresh.enable_caching()
        fresh.compile(solver_signature(types))


def compile_job(job: str, table: Mapping[str, Work] | None = None) -> None:
    """Run one job of ``table`` (default: :func:`jobs`), or the deadbeat solver's
    (:data:`CONTROL`), into the cache."""
    if job == CONTROL:
        # their cached kernels compile on import: the deadbeat solver's, the footholds' least squares
        from . import compiled, footholds_solver  # noqa: F401

        return
    for function, types, bound in (jobs() if table is None else table)[job]:
        _compile(function, types, bound)


def worker(table: Mapping[str, Work]) -> int:
    """A warm-up subprocess: each job name read on standard input compiled (:func:`compile_job`),
    ``done JOB SECONDS`` or ``failed JOB`` on standard output (the error on standard error)."""
    for line in sys.stdin:
        job = line.strip()
        start = time.perf_counter()
        try:
            compile_job(job, table)
        except Exception as exc:  # reported by the controller, which goes on with the others
            print(f"{job}: {type(exc).__name__}: {exc}", file=sys.stderr, flush=True)
            print(f"failed {job}", flush=True)
            continue
        print(f"done {job} {time.perf_counter() - start:.1f}", flush=True)
    return 0


def cores() -> int:
    """The cores this process may run on (its CPU affinity where the system has one)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


@dataclass(frozen=True)
class Warmed:
    """What :func:`warm` did: the ``jobs`` it ran (0: the cache was warm) in ``seconds``, and those
    ``failed`` (``job: last line of its error``; later calls compile them)."""

    jobs: int = 0
    seconds: float = 0.0
    failed: tuple[str, ...] = field(default=())


def warm(
    processes: int | None = None,
    maps=None,
    *,
    table: Mapping[str, Work] | None = None,
    command: list[str] | None = None,
    say: Callable[[str], object] = print,
    progress: bool | None = None,
) -> Warmed:
    """Run every cold job (:func:`cold_jobs`) of the maps named in ``maps`` (None: all, and the
    deadbeat solver) in ``processes`` subprocesses (default: :func:`cores`). ``table`` and
    ``command`` replace the jobs and the subprocess (the suite's: tests/warmup.py); ``say`` gets a
    line before and after (none with a warm cache: nothing starts), ``progress`` draws a bar on
    standard error (:class:`~slipmaps.runtime.api.progress.Bar`: None on a terminal only)."""
    import numba

    if numba.config.DISABLE_JIT:
        return Warmed()
    start = time.perf_counter()
    table = jobs(maps) if table is None else table
    cold = cold_jobs(table, control=maps is None)
    if not cold:
        return Warmed()
    processes = max(1, min(cores() if processes is None else processes, len(cold)))
    if command is None:
        command = [sys.executable, "-m", __name__, "--worker", *(maps or ())]
    say(f"warming numba's cache (empty or stale): {len(cold)} jobs in {processes} processes")
    todo = Phases(cold)
    failed: list[str] = []
    took: dict[str, float] = {}
    with tempfile.TemporaryDirectory(prefix="slipmaps-warmup-") as folder:
        logs = [Path(folder) / f"{i}.log" for i in range(processes)]
        threads = [
            threading.Thread(target=_drive, args=(command, log, todo, failed, took), daemon=True)
            for log in logs
        ]
        for t in threads:
            t.start()
        with Bar(len(cold), "compiling slipmaps' kernels", progress, unit="jobs") as bar:
            alive = threads
            while alive:  # the bar's count, and its clock, move while the jobs run
                alive[0].join(0.25)
                bar.update(todo.ended - bar.done)
                alive = [t for t in threads if t.is_alive()]
    seconds = time.perf_counter() - start
    longest = ", ".join(f"{m} {t:.0f} s" for m, t in sorted(took.items(), key=lambda kv: -kv[1])[:3])
    tail = f"; not compiled (later calls compile them): {'; '.join(failed)}" if failed else ""
    say(f"warmed numba's cache in {seconds:.0f} s (longest: {longest}){tail}")
    return Warmed(len(cold), seconds, tuple(failed))


class Phases:
    """The cold jobs in two phases, each in the order given: a generated module's role kernels (and
    :data:`CONTROL`), then the jobs of one kernel (``module:function``), which start when every job
    of the first phase has finished. A kernel job's kernel calls what the first phase compiles (an
    option choice's kernel calls the iterative core and the zeroth iterate's map): after it, the
    callees load from the cache; beside it, the two processes compiled them twice (measured: the
    zeroth=geyer-vs stance Jacobian 16-26 s in the warm-up, 1.7 s after the jobs of its module and
    of geyer-vs's Jacobians). ``ended`` counts the jobs finished, compiled or not."""

    def __init__(self, jobs: list[str]):
        self._first = [j for j in jobs if ":" not in j]
        self._second = [j for j in jobs if ":" in j]
        self._running = 0  # first-phase jobs taken and not finished
        self._changed = threading.Condition()
        self.ended = 0

    def take(self) -> str | None:
        """The next job (None when none is left); a second-phase job once the first phase is over."""
        with self._changed:
            if self._first:
                self._running += 1
                return self._first.pop(0)
            while self._running:
                self._changed.wait()
            return self._second.pop(0) if self._second else None

    def finished(self, job: str) -> None:
        """``job`` (from :meth:`take`) is done, compiled or not."""
        with self._changed:
            self.ended += 1
            if ":" not in job:
                self._running -= 1
                self._changed.notify_all()


def _drive(command: list[str], log: Path, todo: Phases, failed: list[str], seconds: dict[str, float]) -> None:
    """One subprocess: give it the next job, wait until it says it is done, until none is left."""
    env = {**os.environ, NOTICES_ENV: "0"}  # its own compiles are the bar's, not lines of their own
    with open(log, "w+b") as err:
        proc = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err, text=True, env=env
        )
        try:
            while (job := todo.take()) is not None:
                try:
                    proc.stdin.write(job + "\n")
                    proc.stdin.flush()
                    answer = proc.stdout.readline().split()
                    while answer and answer[0] not in ("done", "failed"):  # something else printed
                        answer = proc.stdout.readline().split()
                except OSError:  # the process ended before it read the job
                    answer = []
                finally:
                    todo.finished(job)
                if answer[:2] == ["done", job]:
                    seconds[job] = float(answer[2])
                else:
                    err.seek(0)
                    last = err.read().decode(errors="replace").strip().splitlines()[-1:]
                    failed.append(f"{job}: {last[0] if last else 'the warm-up process ended'}")
                    if not answer:  # the process ended: leave the rest to the other ones
                        break
        finally:
            if proc.stdin and not proc.stdin.closed:
                try:
                    proc.stdin.close()
                except OSError:
                    pass
            proc.wait()


if __name__ == "__main__":
    if sys.argv[1:2] == ["--worker"]:
        sys.exit(worker(jobs(sys.argv[2:] or None)))
    sys.exit(f"usage: {sys.argv[0]} --worker [MAPS] (the warm-up's subprocess; run `slipmaps warmup`)")
