"""One pipeline for the studies of ``slipmaps accuracy``: measure -> JSON -> Markdown -> PNG.

A :class:`Study` has a ``name`` (its files: ``<name>.json``, ``<name>.md``, ``<name>.png``) and
three steps: :meth:`Study.measure` returns the record, JSON-able data (dicts, lists, strings,
numbers; NaN for a number that could not be measured); :meth:`Study.markdown` renders a record as
the report; :meth:`Study.figure` draws it. :func:`write` runs them in that order for one study and
writes the three files; :mod:`.runner` does it for every study (``slipmaps accuracy``).

Deterministic output: the record is written with 6 significant digits (:func:`to_json`, NaN as
``null``, no timings), and the Markdown and the figure are rendered from the record as the JSON
file holds it (:func:`from_json` of the written text), so the same inputs give byte-identical JSON
and Markdown, and the Markdown is a function of the JSON.
"""

from __future__ import annotations

import json
import os
import platform
from abc import ABC, abstractmethod
from pathlib import Path

from ..api.paths import writing
from .report_format import rounded

__all__ = ["VERSION", "Study", "to_json", "from_json", "machine", "paths", "write", "write_files"]

#: The version of the records' format (the ``version`` key of every docs/*.json).
VERSION = 1


class Study(ABC):
    """A study of ``slipmaps accuracy``: what it measures, how it is reported and drawn."""

    #: The stem of the study's files, e.g. ``"accuracy"`` for docs/accuracy.md, .json, .png.
    name: str

    def applies(self) -> bool:
        """Whether there is anything to measure (a study of the maps that accept k_c != k_d has
        nothing when none is chosen); a study that does not apply writes no file."""
        return True

    @abstractmethod
    def measure(self, show_progress: bool | None = None) -> dict:
        """The record (JSON-able); ``show_progress`` is passed to the progress bars
        (:func:`~slipmaps.runtime.api.progress.progress`) of the long loops."""

    @abstractmethod
    def markdown(self, record: dict, figure_name: str) -> str:
        """The report of ``record`` (as read back from its JSON), linking the figure ``figure_name``."""

    @abstractmethod
    def figure(self, record: dict, path: Path) -> Path:
        """Draw ``record`` into the PNG file ``path``; returns ``path``."""


def to_json(record: dict) -> str:
    """The record's file: ``{"version": VERSION, **record}``, numbers to 6 significant digits."""
    return json.dumps({"version": VERSION, **rounded(record)}, indent=1) + "\n"


def from_json(text: str) -> dict:
    """A record as its file holds it (the ``version`` key removed)."""
    data = json.loads(text)
    data.pop("version", None)
    return data


def paths(md: str | Path) -> tuple[Path, Path, Path]:
    """The Markdown, JSON and PNG files of the study whose report is ``md``."""
    md = Path(md)
    return md, md.with_suffix(".json"), md.with_suffix(".png")


def write(study: Study, md: str | Path, show_progress: bool | None = None) -> list[Path]:
    """Measure ``study`` and write its record (``md`` with suffix .json), its report ``md`` and its
    figure (.png), both rendered from the record as written; returns the three paths in that order
    (report, record, figure)."""
    md, js, png = paths(md)
    text = to_json(study.measure(show_progress))
    with writing(js):
        js.write_text(text, encoding="utf-8")
    record = from_json(text)
    with writing(md):
        md.write_text(study.markdown(record, png.name), encoding="utf-8")
    with writing(png):
        return [md, js, study.figure(record, png)]


def machine() -> str:
    """The machine a study ran on, as its page states it: the CPU's model name and the cores."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} cores"


def write_files(out: str | Path, stem: str, record: dict, render, figures: dict, clip=None) -> list[Path]:
    """A study's files in ``out`` (the studies of ``slipmaps robot``, ``slipmaps footholds``):
    ``<stem>.json`` (``record``, :func:`to_json`), ``<stem>.md`` (``render`` of the record as the
    file holds it), each figure (``file name -> draw(record, path)``) and, with ``clip``, the clip
    ``<stem>.gif`` (``clip(record, path)``), all drawn from the record as written; the paths in
    that order."""
    out = Path(out)
    js, md = out / f"{stem}.json", out / f"{stem}.md"
    text = to_json(record)
    with writing(js):
        js.write_text(text, encoding="utf-8")
    written = from_json(text)
    with writing(md):
        md.write_text(render(written), encoding="utf-8")
    paths = [js, md, *(draw(written, out / name) for name, draw in figures.items())]
    if clip is not None:
        paths.append(clip(written, out / f"{stem}.gif"))
    return paths
