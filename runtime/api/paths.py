"""Paths a command writes, checked before any work: one helper for every file and directory.

:func:`writable_file` (``compare --plot``, ``gait --figure``, ``accuracy --out FILE.md``) and
:func:`writable_dir` (``sweep --out``, ``accuracy --out DIR``, a sweep's output directory in
:class:`~.sweep_store.Store`) create a missing directory and raise a one-line ValueError naming
``what`` (the flag as typed, or the argument's name) and the path when it cannot be written: an
existing file where a directory belongs (also a file as a component of the path, ``c.pdf/x.png``
with ``c.pdf`` a file), a directory where a file belongs, a suffix the writer does not know, a
directory that cannot be created or is not writable.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

__all__ = ["writable_file", "writable_dir"]


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
    return None


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
