"""Paths a command writes, checked before any work: one helper for every file and directory.

:func:`writable_file` (``compare --plot``, ``gait --figure``, ``accuracy --out FILE.md``) and
:func:`writable_dir` (``sweep --out``, ``accuracy --out DIR``, a sweep's output directory in
:class:`~.sweep_store.Store`) create a missing directory and raise a one-line ValueError naming
``what`` (the flag as typed, or the argument's name) and the path when it cannot be written: an
existing file where a directory belongs (also a file as a component of the path, ``c.pdf/x.png``
with ``c.pdf`` a file), a directory where a file belongs, a suffix the writer does not know, a
directory that cannot be created or is not writable. Writability is tried, not inferred from
permissions: a probe file is created in the directory and removed (``/proc`` passes a permission
check and refuses every new file).

:func:`writing` is the one guard around every write the package does (figures, GIFs, JSON, CSV,
Parquet, reports): an OSError while writing becomes a one-line ValueError naming the path and the
reason (the command line prints it and exits 2).
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path

__all__ = ["writable_file", "writable_dir", "writing"]


@contextlib.contextmanager
def writing(path: str | os.PathLike, what: str | None = None) -> Iterator[Path]:
    """Guard one write of ``path``: an OSError inside becomes ValueError ``[what ]path: reason``."""
    try:
        yield Path(path)
    except OSError as exc:
        label = f"{what} {path}" if what else f"cannot write {path}"
        raise ValueError(f"{label}: {exc.strerror or exc}") from None


def plain_ticks(fig) -> None:
    """Every linear axis of ``fig`` labels its ticks with their values, never as an offset plus
    differences (matplotlib writes an apex height that varies by 1e-6 about 1 m as ``1e-6 +
    9.9999e-1``)."""
    from matplotlib.ticker import ScalarFormatter

    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            formatter = axis.get_major_formatter()
            if isinstance(formatter, ScalarFormatter):
                formatter.set_useOffset(False)


def save_figure(fig, path: str | os.PathLike, dpi: int = 110) -> Path:
    """Save a matplotlib figure to ``path`` with plain tick labels (:func:`plain_ticks`; an OSError
    as :func:`writing`'s ValueError) and close it, whatever happened; returns the path. Every figure
    the package writes goes through here."""
    import matplotlib.pyplot as plt

    try:
        plain_ticks(fig)
        with writing(path):
            fig.savefig(path, dpi=dpi)
    finally:
        plt.close(fig)
    return Path(path)


def _probe(folder: Path) -> str | None:
    """Why a file cannot be created in ``folder`` (a probe created and removed), or None."""
    try:
        fd, name = tempfile.mkstemp(prefix=".slipmaps-probe-", dir=folder)
    except OSError as exc:
        return f"cannot create a file in {folder}: {exc.strerror or exc}"
    os.close(fd)
    with contextlib.suppress(OSError):
        os.remove(name)
    return None


def _problem(folder: Path) -> str | None:
    """Why files cannot be written into directory ``folder`` (created when missing), or None."""
    for part in (*reversed(folder.parents), folder):
        if not part.exists():
            break
        if not part.is_dir():
            return f"cannot create the directory {folder}: {part} is a file, not a directory"
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        return f"cannot create the directory {folder}: {exc.strerror or exc}"
    if not os.access(folder, os.W_OK):
        return f"the directory {folder} is not writable"
    return _probe(folder)


def writable_dir(what: str, path: str | os.PathLike) -> Path:
    """``path`` as a directory to write into, created (with its parents) when missing; ValueError
    (one line: ``what``, the path and the reason) when it cannot be."""
    folder = Path(path)
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"{what} {path} is a file, not a directory; give a directory")
    problem = _problem(folder)
    if problem:
        raise ValueError(f"{what} {path}: {problem}")
    return folder


def writable_file(
    what: str,
    path: str | os.PathLike,
    suffixes: Sequence[str] | None = None,
    *,
    described: str = "a file",
    example: str = "out",
) -> Path:
    """``path`` as a file to write: not a directory, its suffix one of ``suffixes`` (without the dot,
    any case; None: any suffix), its directory created when missing and writable; ValueError (one
    line: ``what``, the path and the reason) otherwise. ``described`` names the file in the
    suffix message (``give an image file name ending in .png, ...``); ``example`` is the file name
    suggested when ``path`` is a directory."""
    target = Path(path)
    if target.is_dir():
        suffix = f".{suffixes[0]}" if suffixes else ""
        raise ValueError(f"{what} {path} is a directory; give a file, e.g. {target / (example + suffix)}")
    if suffixes is not None and target.suffix.lower().lstrip(".") not in suffixes:
        raise ValueError(f"{what} {path}: give {described} name ending in .{', .'.join(suffixes)}")
    problem = _problem(target.parent)
    if problem:
        raise ValueError(f"{what} {path}: {problem}")
    return target
