"""Test configuration: Hypothesis' profile, and numba's cache warmed once before the suite runs.

Hypothesis: every run prints, with a failing example, the ``@reproduce_failure`` line that replays
it (``print_blob``), and no example fails for the machine's load (no deadline, no health check on
slow generation): a failure is the code's, reproducible from what the run printed. Locally
Hypothesis explores new examples each run (and keeps failures in .hypothesis/); under CI (``CI``
set) it runs derandomized, so a red run is reproducible as it is.

numba: on an empty cache most of a first run is numba compiling the kernels, which every xdist
worker did again for itself. When the run is the whole suite (no test paths given, or the tests
directory), the controller (or the only process, without xdist) first compiles every kernel the
suite calls that is missing from the cache, in as many processes as the run has workers
(``tests/warmup.py``); the workers then load them. With a warm cache that is a check of the
cache's indexes (about a second) and nothing else. ``SLIPMAPS_WARMUP=0`` turns it off, ``=1``
forces it for any paths.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile(
    "suite", print_blob=True, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile("ci", parent=settings.get_profile("suite"), derandomize=True)
settings.load_profile("ci" if os.environ.get("CI") else "suite")

TESTS = Path(__file__).resolve().parent


def _warmup_processes(config: pytest.Config) -> int:
    """How many processes warm numba's cache before the tests (0: none): the xdist workers' count in
    the controller, the cores without xdist; none in a worker, for a subset of the suite, or when
    only collecting."""
    if os.environ.get("PYTEST_XDIST_WORKER") or config.option.collectonly:
        return 0
    wanted = os.environ.get("SLIPMAPS_WARMUP", "")
    if wanted == "0":
        return 0
    whole = all(Path(str(a).split("::")[0]).resolve() in (TESTS, TESTS.parent) for a in config.args)
    if wanted != "1" and not whole:
        return 0
    workers = getattr(config.option, "numprocesses", None) or 0  # xdist's -n, resolved ("auto": cores)
    cores = os.cpu_count() or 1
    return max(1, min(workers, cores) if workers else cores)


@pytest.hookimpl(tryfirst=True)  # before xdist starts its workers (its own hook runs last)
def pytest_sessionstart(session: pytest.Session) -> None:
    processes = _warmup_processes(session.config)
    if not processes:
        return
    import warmup

    terminal = session.config.pluginmanager.get_plugin("terminalreporter")
    warmup.warm(processes, say=terminal.write_line if terminal is not None else print)


def pytest_configure(config: pytest.Config) -> None:
    # xdist queues a run's files by their number of tests (most first); the order below replaces it
    if hasattr(config.option, "loadscopereorder"):
        config.option.loadscopereorder = False


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Queue the files for ``--dist loadfile`` longest first, as the warm-up does its jobs: a file
    with a test marked ``slow`` first (each takes a minute or more: a SymPy build, the kernels'
    first compiles in a copy of the project), then by number of tests, most first (xdist's own
    order). xdist hands a worker the next file as it finishes one; a long file queued last (xdist's
    order put the two tutorials, with four and six tests, at the end) runs alone while the other
    worker idles. Stable: within a file, and between files of the same rank, collection order."""
    files: dict[str, list[pytest.Item]] = {}
    for item in items:
        files.setdefault(item.nodeid.split("::", 1)[0], []).append(item)

    def rank(group: list[pytest.Item]) -> tuple[bool, int]:
        return (not any(i.get_closest_marker("slow") for i in group), -len(group))

    items[:] = [item for group in sorted(files.values(), key=rank) for item in group]


@pytest.fixture(scope="session")
def c_export(tmp_path_factory, request):
    """The C target's library (``slipmaps generate --target c``) in a directory of this session,
    each source compiled once with the export's strict flags into an object (``slipmaps.o``,
    ``slipmaps_deadbeat.o``, ``slipmaps_swing.o``) that the C tests link into their libraries.
    Built once for the whole run: the xdist workers share it (the first builds it under a file
    lock). Skips without a compiler."""
    import subprocess

    from slipmaps.runtime.export.clib import STRICT, compiler

    cc = compiler()
    if cc is None:
        pytest.skip("no C compiler (set CC, or install gcc or clang)")
    from slipmaps.derive import ctarget

    base = tmp_path_factory.getbasetemp()
    root = base.parent if hasattr(request.config, "workerinput") else base
    out = root / "c_export"
    with open(root / "c_export.lock", "w") as lock:
        try:
            import fcntl

            fcntl.flock(lock, fcntl.LOCK_EX)
        except ImportError:  # no POSIX locks: each worker builds its own copy
            out = base / "c_export"
        if not (out / ".built").exists():
            out.mkdir(exist_ok=True)
            ctarget.write(out)
            procs = [
                subprocess.Popen([cc, *STRICT, "-fPIC", "-c", src, "-o", src.replace(".c", ".o")], cwd=out)
                for src in ctarget.SOURCES
            ]
            assert all(p.wait() == 0 for p in procs), "the exported C does not compile warning-free"
            (out / ".built").touch()
    return out
