"""The source checkout slipmaps runs from, if any: where ``slipmaps accuracy`` writes its reports.

A checkout (a clone used through ``pip install -e .`` or ``PYTHONPATH``) has this package's sources
at ``<root>/runtime/`` beside ``<root>/pyproject.toml`` (naming the project ``slipmaps``) and
``<root>/docs/``. An installed wheel has none of them next to it, so :func:`checkout_root` is None
there and a command that writes reports must be told where (``--out``), never a relative ``docs/``.
"""

from __future__ import annotations

import re
from pathlib import Path

__all__ = ["checkout_root", "docs_dir"]

#: The runtime's source directory, symlinks resolved (``<root>/runtime`` in a checkout; this file is
#: ``runtime/studies/checkout.py``).
_HERE = Path(__file__).resolve().parent.parent
_NAME = re.compile(r'^name\s*=\s*"slipmaps"\s*$', re.MULTILINE)


def checkout_root(here: Path = _HERE) -> Path | None:
    """The checkout's root directory when ``here`` (the runtime sources) lies in one, else None."""
    root = here.parent
    pyproject = root / "pyproject.toml"
    if not (pyproject.is_file() and (root / "docs").is_dir() and here.name == "runtime"):
        return None
    try:
        text = pyproject.read_text(encoding="utf-8")
    except OSError:
        return None
    return root if _NAME.search(text) else None


def docs_dir(here: Path = _HERE) -> Path | None:
    """The checkout's ``docs/`` (absolute), or None when slipmaps does not run from a checkout."""
    root = checkout_root(here)
    return None if root is None else root / "docs"
