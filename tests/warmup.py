"""Compile slipmaps' kernels once into numba's disk cache before the test workers start.

On an empty cache most of a first run of the suite is numba compiling kernels, and with
``pytest -n N`` every worker compiled the same kernels: N times the work, on the same cores. The
suite's controller (tests/conftest.py) calls :func:`warm` first: it finds the jobs (:func:`jobs`)
with a kernel that has no entry in numba's cache for the types the suite calls it with, and runs
those in ``processes`` subprocesses that take the jobs one at a time, longest first (an estimate:
:func:`_order`), as they finish: the jobs of the modules' role kernels first, then, once those have
finished, the jobs of single kernels that call them (:class:`Phases`). The workers then load the
kernels from the cache. With a warm cache it imports the generated modules and reads their cache
indexes: no subprocess.

A job is a generated module's role kernels at the maps' default options (every role of every map
and half-stance map, and the model's kernels: the index, ``runtime/api/index.py``), the deadbeat
solver (:data:`CONTROL`), or one kernel that tests call beyond those (:func:`kernel_jobs`: the other
choices of a specialized option, every map's Jacobians' batch forms, the exact
simulator's external kernels), each of which a worker compiled for itself before.

numba keys a cache entry by the exact signature a compile asks for. A kernel is compiled
(``dispatcher.compile``, not run) for the types every caller passes (C-contiguous float64,
writable; int64 statuses; float64 scalars), so the entry is the one a call looks up; a kernel the
deadbeat solver binds as a first-class function is looked up by its full signature, int64 return
type included (``MODEL`` of runtime/control/compiled.py), a second entry the warm-up saves too.
What no entry can serve, every process that needs it compiles: the solver bound to a map's kernels
(``compiled.bind``: a closure over two dispatchers, whose key pickles them with an identity of
their process), test-local closures (test_exact_compiled.py's integrator runs) and the modules
test_ir.py generates for itself.

The subprocesses are a plain ``python tests/warmup.py --worker`` reading job names on standard
input, so a failure there only leaves work to the workers, as without the warm-up.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import threading
import time
from functools import cache
from pathlib import Path

#: The job that compiles the deadbeat solver's and the footholds' cached kernels
#: (runtime/control/compiled.py, footholds_solver.py: they compile when imported), not a generated
#: module.
CONTROL = "control"

#: Roles whose kernels tests call at every choice of a specialized option (the zeroth iterate of
#: ``iterative``), not only at its default: True with the batch form. test_codegen.py runs every
#: scalar kernel of the map modules, test_accuracy.py the stance's batch form at every zeroth
#: iterate (the accuracy record), test_jacobian.py the stance Jacobian at every option choice,
#: test_c_export.py every role's row kernel at every choice.
CHOICE_ROLES = {"stance": True, "apex_return": False, "stance_jacobian": False, "apex_return_jacobian": False}
#: The exact simulator's external kernels (generated/exact_stance.py) that tests call directly
#: (test_exact_compiled.py, test_exact_rtol.py); each inlines the DOP853 integrator.
EXACT_KERNELS = (
    "stance_jacobian",
    "stance_into",
    "stance",
    "decompression",
    "state_at",
    "compression",
    "stance_evaluations",
)
#: Roles the deadbeat solver binds as first-class functions (runtime/control: deadbeat.py, bottom.py).
SOLVER_ROLES = ("apex_return", "apex_return_jacobian", "apex")


def role_specs() -> dict[str, list]:
    """Every role kernel's spec (:class:`~slipmaps.runtime.api.index.KernelSpec`) at the maps' default
    options, by generated module: the kernels most tests call, from several files, so from both
    workers. (The other choices of a specialized option: :func:`kernel_jobs`.)"""
    from slipmaps.runtime.api import index

    by_module: dict[str, dict] = {}
    for m in (*index.maps(), *index.halves()):
        for s in m.kernels.values():  # at the map's default options (a specialized one's default choice)
            by_module.setdefault(s.module, {})[s.name] = s
    for s in index.model_kernels().values():
        by_module.setdefault(s.module, {})[s.name] = s
    return {module: list(specs.values()) for module, specs in sorted(by_module.items())}


def signatures(spec, row: bool = True, rows: bool | None = None) -> list[tuple]:
    """``(function, argument types)`` the warm-up compiles for ``spec``: the role kernel at the types
    of ``kernel(x, p, out)`` (unless ``row`` is False), and its batch form at those of
    ``kernel_rows(X, P, OUT, STATUS)`` (C-contiguous float64, writable; int64 statuses) when
    ``rows``, by default unless it is a Jacobian's (its batch form: :func:`kernel_jobs`)."""
    import numba
    import numpy as np

    kernel, batch = spec.functions()
    nx, np_, width = len(spec.x), max(1, len(spec.p)), spec.width
    out = [(kernel, (np.empty(nx), np.empty(np_), np.empty(width)))] if row else []
    if rows if rows is not None else not spec.wrt:
        args = (np.empty((1, nx)), np.empty((1, np_)), np.empty((1, width)), np.empty(1, np.int64))
        out.append((batch, args))
    return [(f, tuple(map(numba.typeof, args))) for f, args in out]


def _external_types(function) -> tuple:
    """The types tests call an external kernel of exact_stance with: float64 scalars, ``s`` its
    parameter record (``Stance``, float64 fields), ``out`` a C-contiguous float64 array."""
    import inspect

    import numba
    import numpy as np
    from slipmaps.generated import exact_stance

    record = exact_stance.Stance(*[0.0] * len(exact_stance.Stance._fields))
    by_name = {"s": numba.typeof(record), "out": numba.typeof(np.empty(1))}
    names = inspect.signature(function.py_func).parameters
    return tuple(by_name.get(name, numba.float64) for name in names)


def kernel_jobs() -> dict[str, list[tuple]]:
    """The jobs of one kernel (``module:function``): ``(function, argument types)`` to compile, for
    what tests call beyond the role kernels at the defaults (:data:`CHOICE_ROLES`,
    :data:`EXACT_KERNELS`)."""
    from slipmaps.generated import exact_stance
    from slipmaps.runtime.api import index

    out: dict[str, list[tuple]] = {}
    for m in (*index.maps(), *index.halves()):
        for suffix in sorted(set(m.choices.values())):
            for role, rows in CHOICE_ROLES.items():
                default = m.kernels.get(role)
                spec = default.chosen(suffix) if default is not None else None
                if spec is not None and spec.name != default.name:
                    out[f"{spec.module}:{spec.name}"] = signatures(spec, rows=rows)
    for m in index.maps():  # every map's Jacobians' batch forms (test_c_export.py, test_jacobian.py)
        for role in ("stance_jacobian", "apex_return_jacobian"):
            spec = m.kernels[role]
            out[f"{spec.module}:{spec.name}_rows"] = signatures(spec, row=False, rows=True)
    for name in EXACT_KERNELS:
        function = getattr(exact_stance, name)
        out[f"exact_stance:{name}"] = [(function, _external_types(function))]
    return out


@cache
def jobs() -> dict[str, list[tuple]]:
    """Every job: its ``(function, argument types, bound)`` to compile, ``bound`` True for a kernel
    the deadbeat solver binds (:func:`solver_signature`): a generated module's role kernels at the
    defaults (:func:`role_specs`) by the module's name, and :func:`kernel_jobs`."""
    from slipmaps.runtime.api import index

    bound = {
        (s.module, s.name)
        for m in (*index.maps(), *index.halves())
        for role, s in m.kernels.items()
        if role in SOLVER_ROLES
    }
    out: dict[str, list[tuple]] = {}
    for module, specs in role_specs().items():
        out[module] = [
            (f, types, (s.module, s.name) in bound and f is s.functions()[0])
            for s in specs
            for f, types in signatures(s)
        ]
    for job, work in kernel_jobs().items():
        out[job] = [(f, types, False) for f, types in work]
    return out


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
    except Exception:  # numba's internals moved: assume warm, the workers compile what is missing
        return True


def _keys(types: tuple, bound: bool) -> list:
    return [types, solver_signature(types)] if bound else [types]


def _generated_file(module: str) -> Path:
    import slipmaps.generated

    return Path(slipmaps.generated.__file__).parent / f"{module}.py"


def _order(job: str) -> tuple:
    """The estimated longest jobs first: those of the exact simulator's modules (generated/
    exact_stance.py and the modules that import it: their kernels inline its DOP853 integrator,
    the longest compiles), then by the size of the job's module; a module's jobs in the order of
    :func:`jobs` (its role kernels, then :func:`kernel_jobs`'s, :data:`EXACT_KERNELS` longest first)."""
    module = job.split(":")[0]
    text = _generated_file(module).read_text()
    head = text.split('"""', 1)[0]  # the header's "Depends on" list names the modules it imports
    exact = module == "exact_stance" or "exact_stance.py" in head
    return (not exact, -len(text), list(jobs()).index(job))


def cold_jobs() -> list[str]:
    """The jobs with a kernel missing from numba's cache, longest first (:func:`_order`), after
    :data:`CONTROL` when any is cold."""
    cold = [
        job
        for job, work in jobs().items()
        if not all(_cached(f, key) for f, types, bound in work for key in _keys(types, bound))
    ]
    cold.sort(key=_order)
    return [CONTROL, *cold] if cold else []  # the solver: about a minute, so first


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


def compile_job(job: str) -> None:
    """Run one job (:func:`jobs`), or the deadbeat solver's (:data:`CONTROL`), into the cache."""
    if job == CONTROL:
        import slipmaps.runtime.control.compiled  # noqa: F401  (its cached kernels compile on import)
        import slipmaps.runtime.control.footholds_solver  # noqa: F401  (the footholds' least squares, too)

        return
    for function, types, bound in jobs()[job]:
        _compile(function, types, bound)


def warm(processes: int, say=print) -> float:
    """Run every cold job (:func:`cold_jobs`) in ``processes`` subprocesses; returns the
    seconds it took (0 with a warm cache, when nothing starts). ``say`` gets a line before and after."""
    import numba

    if numba.config.DISABLE_JIT:
        return 0.0
    start = time.perf_counter()
    cold = cold_jobs()
    if not cold:
        return 0.0
    processes = max(1, min(processes, len(cold)))
    say(f"warming numba's cache (empty or stale): {len(cold)} jobs in {processes} processes")
    todo = Phases(cold)
    failed: list[str] = []
    took: dict[str, float] = {}
    with tempfile.TemporaryDirectory(prefix="slipmaps-warmup-") as folder:
        logs = [Path(folder) / f"{i}.log" for i in range(processes)]
        threads = [threading.Thread(target=_drive, args=(log, todo, failed, took)) for log in logs]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    seconds = time.perf_counter() - start
    longest = ", ".join(f"{m} {t:.0f} s" for m, t in sorted(took.items(), key=lambda kv: -kv[1])[:3])
    tail = f"; not compiled (the workers compile them): {'; '.join(failed)}" if failed else ""
    say(f"warmed numba's cache in {seconds:.0f} s (longest: {longest}){tail}")
    return seconds


class Phases:
    """The cold jobs in two phases, each in the order given: a generated module's role kernels (and
    :data:`CONTROL`), then the jobs of one kernel (``module:function``, :func:`kernel_jobs`), which
    start when every job of the first phase has finished. A kernel job's kernel calls what the first
    phase compiles (an option choice's kernel calls the iterative core and the zeroth iterate's
    map): after it, the callees load from the cache; beside it, the two processes compiled them
    twice (measured: the zeroth=geyer-vs stance Jacobian 16-26 s in the warm-up, 1.7 s after the
    jobs of its module and of geyer-vs's Jacobians)."""

    def __init__(self, jobs: list[str]):
        self._first = [j for j in jobs if ":" not in j]
        self._second = [j for j in jobs if ":" in j]
        self._running = 0  # first-phase jobs taken and not finished
        self._changed = threading.Condition()

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
        if ":" not in job:
            with self._changed:
                self._running -= 1
                self._changed.notify_all()


def _drive(log: Path, todo: Phases, failed: list[str], seconds: dict[str, float]) -> None:
    """One subprocess: give it the next job, wait until it says it is done, until none is left."""
    with open(log, "w+b") as err:
        proc = subprocess.Popen(
            [sys.executable, __file__, "--worker"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=err,
            text=True,
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
                proc.stdin.close()
            proc.wait()


def _worker() -> int:
    for line in sys.stdin:
        job = line.strip()
        start = time.perf_counter()
        try:
            compile_job(job)
        except Exception as exc:  # reported by the controller, which goes on with the others
            print(f"{job}: {type(exc).__name__}: {exc}", file=sys.stderr, flush=True)
            print(f"failed {job}", flush=True)
            continue
        print(f"done {job} {time.perf_counter() - start:.1f}", flush=True)
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--worker"]:
        sys.exit(_worker())
    n = int(sys.argv[1]) if len(sys.argv) > 1 else (os.cpu_count() or 1)
    warm(n)
