"""Compile slipmaps' kernels once into numba's disk cache before the test workers start.

On an empty cache most of a first run of the suite is numba compiling kernels, and with
``pytest -n N`` every worker compiled the same kernels: N times the work, on the same cores. The
suite's controller (tests/conftest.py) calls :func:`warm` first: it finds the generated kernel
modules whose role kernels (every role of every map and half-stance map at its default options,
and the model's kernels: the index, ``runtime/api/index.py``) have no fresh entry in numba's
cache, and compiles those in ``processes`` subprocesses that take the modules one at a time,
largest first, as they finish. The workers then load the kernels from the cache. With a
warm cache it imports the generated modules and reads their cache indexes: no subprocess.

A role kernel and its batch form (a Jacobian's: the kernel alone; its batch form is used by a few
tests) are compiled (``dispatcher.compile``, not run) for the array types every caller passes
(C-contiguous float64, writable; int64 statuses), so the cache entry is the one a call looks up.
The subprocesses are a plain ``python tests/warmup.py --worker`` reading module names on standard
input, so a failure there only leaves work to the workers, as without the warm-up.
"""

from __future__ import annotations

import os
import queue
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

#: The job that compiles the deadbeat solver's cached kernels (runtime/control/compiled.py: they
#: compile when it is imported), not a generated module.
CONTROL = "control"


def role_specs() -> dict[str, list]:
    """Every role kernel's spec (:class:`~slipmaps.runtime.api.index.KernelSpec`) at the maps' default
    options, by generated module: the kernels most tests call, from several files, so from both
    workers. (The other choices of a specialized option are compiled by the few tests that ask for
    them, in one worker; most of their kernels no test calls.)"""
    from slipmaps.runtime.api import index

    by_module: dict[str, dict] = {}
    for m in (*index.maps(), *index.halves()):
        for s in m.kernels.values():  # at the map's default options (a specialized one's default choice)
            by_module.setdefault(s.module, {})[s.name] = s
    for s in index.model_kernels().values():
        by_module.setdefault(s.module, {})[s.name] = s
    return {module: list(specs.values()) for module, specs in sorted(by_module.items())}


def signatures(spec) -> list[tuple]:
    """``(function, argument types)`` the warm-up compiles for ``spec``: the role kernel at the types
    of ``kernel(x, p, out)``, and unless it is a Jacobian's its batch form at those of
    ``kernel_rows(X, P, OUT, STATUS)`` (C-contiguous float64, writable; int64 statuses)."""
    import numba
    import numpy as np

    row, rows = spec.functions()
    nx, np_, width = len(spec.x), max(1, len(spec.p)), spec.width
    out = [(row, (np.empty(nx), np.empty(np_), np.empty(width)))]
    if not spec.wrt:  # a Jacobian's batch form: a few tests, one worker (3-4 s each)
        batch = (np.empty((1, nx)), np.empty((1, np_)), np.empty((1, width)), np.empty(1, np.int64))
        out.append((rows, batch))
    return [(f, tuple(map(numba.typeof, args))) for f, args in out]


def _fresh(dispatcher) -> bool:
    """Whether numba's cache holds an entry of ``dispatcher`` for its source as it is now (numba's
    own check: the index's stamp against the file's); True when that cannot be read."""
    try:
        return bool(dispatcher._cache._cache_file._load_index())
    except Exception:  # numba's internals moved: assume warm, the workers compile what is missing
        return True


def cold_modules() -> list[str]:
    """The generated modules with a role kernel missing from numba's cache, largest first (the
    longest compiles start first), after :data:`CONTROL` when any is cold."""
    specs = role_specs()
    cold = [
        module
        for module, kernels in specs.items()
        if not all(_fresh(f) for spec in kernels for f, _ in signatures(spec))
    ]
    import slipmaps.generated

    generated = Path(slipmaps.generated.__file__).parent
    cold.sort(key=lambda module: -(generated / f"{module}.py").stat().st_size)
    return [CONTROL, *cold] if cold else []  # the solver: about a minute, so first


def compile_module(module: str) -> None:
    """Compile ``module``'s role kernels (or the deadbeat solver's, :data:`CONTROL`) into the cache."""
    if module == CONTROL:
        import slipmaps.runtime.control.compiled  # noqa: F401  (its cached kernels compile on import)

        return
    for spec in role_specs()[module]:
        for function, types in signatures(spec):
            function.compile(types)  # what a call with those types compiles, without running it


def warm(processes: int, say=print) -> float:
    """Compile every cold module (:func:`cold_modules`) in ``processes`` subprocesses; returns the
    seconds it took (0 with a warm cache, when nothing starts). ``say`` gets a line before and after."""
    import numba

    if numba.config.DISABLE_JIT:
        return 0.0
    start = time.perf_counter()
    jobs = cold_modules()
    if not jobs:
        return 0.0
    processes = max(1, min(processes, len(jobs)))
    say(f"warming numba's cache (empty or stale): {len(jobs)} kernel modules in {processes} processes")
    todo: queue.Queue[str] = queue.Queue()
    for job in jobs:
        todo.put(job)
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


def _drive(log: Path, todo: queue.Queue, failed: list[str], seconds: dict[str, float]) -> None:
    """One subprocess: give it the next module, wait until it says it is done, until none is left."""
    with open(log, "w+b") as err:
        proc = subprocess.Popen(
            [sys.executable, __file__, "--worker"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=err,
            text=True,
        )
        try:
            while True:
                try:
                    module = todo.get_nowait()
                except queue.Empty:
                    break
                proc.stdin.write(module + "\n")
                proc.stdin.flush()
                answer = proc.stdout.readline().split()
                while answer and answer[0] not in ("done", "failed"):  # something else printed
                    answer = proc.stdout.readline().split()
                if answer[:2] == ["done", module]:
                    seconds[module] = float(answer[2])
                else:
                    err.seek(0)
                    last = err.read().decode(errors="replace").strip().splitlines()[-1:]
                    failed.append(f"{module}: {last[0] if last else 'the warm-up process ended'}")
                    if not answer:  # the process ended: leave the rest to the other ones
                        break
        finally:
            if proc.stdin and not proc.stdin.closed:
                proc.stdin.close()
            proc.wait()


def _worker() -> int:
    for line in sys.stdin:
        module = line.strip()
        start = time.perf_counter()
        try:
            compile_module(module)
        except Exception as exc:  # reported by the controller, which goes on with the others
            print(f"{module}: {type(exc).__name__}: {exc}", file=sys.stderr, flush=True)
            print(f"failed {module}", flush=True)
            continue
        print(f"done {module} {time.perf_counter() - start:.1f}", flush=True)
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--worker"]:
        sys.exit(_worker())
    n = int(sys.argv[1]) if len(sys.argv) > 1 else (os.cpu_count() or 1)
    warm(n)
