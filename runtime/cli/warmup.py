"""``slipmaps warmup [MAPS]``: compile the kernels into numba's disk cache now, on every core.

A first call of a kernel compiles it (seconds to a minute each on an empty cache, a line on
standard error saying so); ``slipmaps warmup`` compiles them ahead, in one process per core
(``--processes N``), longest first, with a progress bar on a terminal (``--no-progress``: none):
with no MAPS every map, half-stance map and model kernel and the deadbeat solver; with MAPS (names
of ``slipmaps maps``) those maps' kernels. With a warm cache it says so and starts nothing. The
mechanism is :mod:`slipmaps.runtime.control.warmup`, the test suite's warm-up too. Exit status 1
when a job did not compile (its error named; later calls compile it), 0 otherwise.
"""

from __future__ import annotations

import argparse

__all__ = ["add_parser", "run"]


def add_parser(sub) -> argparse.ArgumentParser:
    """Add the ``warmup`` subcommand to the subparsers ``sub``."""
    p = sub.add_parser(
        "warmup",
        help="compile the kernels into numba's cache now, on every core (first calls then load them)",
        description="Compile slipmaps' kernels into numba's disk cache ahead, in one process per core, "
        "longest first, with a progress bar on a terminal: with no MAPS every map, half-stance map and "
        "model kernel and the deadbeat solver; with MAPS (see `slipmaps maps`) those maps' kernels. A "
        "warm cache starts nothing.",
        epilog="exit status: 0 compiled (or already cached); 1 a job did not compile (named; later calls "
        "compile it); 2 a user error.",
    )
    p.add_argument("maps", nargs="*", metavar="MAP", help="a map or half-stance map (default: all)")
    p.add_argument(
        "--processes", type=int, default=None, metavar="N", help="compiling processes (default: one per core)"
    )
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    return p


def run(args: argparse.Namespace) -> int:
    from ..control import warmup

    if args.processes is not None and args.processes < 1:
        raise ValueError(f"--processes must be a positive number of processes, got {args.processes}")
    maps = args.maps or None
    if maps is not None:
        try:
            warmup.jobs(maps)  # the names checked before any work
        except ValueError as exc:
            raise ValueError(f"MAP: {exc}") from None
    done = warmup.warm(
        args.processes,
        maps,
        say=lambda line: print(line, flush=True),
        progress=False if args.no_progress else None,
    )
    if not done.jobs:
        print("numba's cache already holds every kernel asked for: nothing to compile")
    return 1 if done.failed else 0
