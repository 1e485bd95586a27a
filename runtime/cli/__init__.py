"""The ``slipmaps`` command line: one module per command, the parser and ``main`` in :mod:`.app`."""

from .app import build_parser, main

__all__ = ["build_parser", "main"]
