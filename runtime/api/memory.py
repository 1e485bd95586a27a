"""Memory a piece of work needs, checked against the machine's before anything is allocated.

One check for every caller that can be asked for more than the machine holds: the public batches
(``Call.check_memory``, :mod:`.calls`; the deadbeat batch), runs (``slipmaps.run``,
runtime/control/runs.py) and viability studies (runtime/analysis/viability_map.py), each before it
copies or allocates its rows. Each states its own need in bytes (its arrays: rows times bytes per
row); :func:`check` compares it with :func:`available` and refuses, in one line with the estimate,
what does not fit, so that a user gets that line at once instead of a ``MemoryError`` after
seconds of allocating (a 10^9-row apex return allocated 8 GB in 18.8 s before it).
"""

from __future__ import annotations

import os

__all__ = ["FEW_ROWS", "SMALL", "available", "check"]

#: Needs below this many bytes are not checked (reading the machine's memory costs about 20 us, a
#: scalar call's few times; no machine that runs numba lacks 64 MB).
SMALL = 64 * 2**20
#: A batch of at most this many rows needs less than :data:`SMALL` whatever its kernel (the widest
#: row, geyer-vs's apex-return Jacobian, takes 1,112 bytes; a test checks every role), so it is not
#: estimated: a batch of a few rows costs what a scalar call does.
FEW_ROWS = 16_384


def available() -> int | None:
    """The machine's available memory in bytes: Linux's MemAvailable (free memory and the caches
    it can drop), else the physical memory; None when neither can be read."""
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        return None


def _gb(size: float) -> str:
    """Bytes in GB, three digits (``0.001``, ``22.1``, ``152``), or whole above a thousand (``9,200``)."""
    return f"{size / 1e9:,.0f}" if size >= 1e12 else f"{size / 1e9:.3g}"


def check(need: int, what: str, advice: str, have: int | None = None) -> int:
    """``need`` (bytes), unless it exceeds ``have`` (default: :func:`available`; not read for a
    need below :data:`SMALL`): then ValueError, one line, ``{what} about N GB of memory, more than
    the M GB available: {advice}`` (``what`` with its verb: "1,000 rows need")."""
    need = int(need)
    if have is None and need < SMALL:
        return need
    have = available() if have is None else have
    if have is not None and need > have:
        gb = f"about {_gb(need)} GB of memory, more than the {_gb(have)} GB available"
        raise ValueError(f"{what} {gb}: {advice}")
    return need
