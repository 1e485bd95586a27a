"""A sweep's output directory: its manifest, one file per chunk, resuming, the combined file.

Layout of ``OUT/``::

    manifest.json            the definition, its sha256 (with the format), rows, chunks, columns, units
    chunks/part-00000.csv    chunk 0 (rows 0 .. chunk_rows-1), self-describing (sweep_files)
    chunks/part-00000.json   its row count and rows per status
    sweep.csv                all chunks in one file (optional, when every chunk is written)
    summary.json             rows, rows OK, rows per status (when every chunk is written)

A chunk is written to a temporary name and renamed, its ``.json`` before its data file, so a chunk
whose data file exists is complete: an interrupted sweep resumes from those. Opening a directory
that holds a different sweep (another hash) or files that are not a sweep is a ValueError.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterator, Sequence
from pathlib import Path

import numpy as np

from ..api.frames import to_pandas
from ..api.paths import writable_dir, writing
from .files import check_format, combine, csv_header, read
from .spec import Sweep

__all__ = ["Store", "read_sweep", "iter_sweep"]

MANIFEST = "manifest.json"
VERSION = 1


def _write_atomic(path: Path, data: bytes) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    with writing(path), open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)


def _json_bytes(obj) -> bytes:
    return (json.dumps(obj, indent=2, sort_keys=False) + "\n").encode()


class Store:
    """The directory ``out`` of ``sweep`` written as ``fmt``: created, or reopened to resume."""

    def __init__(self, out: str | Path, sweep: Sweep, fmt: str) -> None:
        self.fmt = check_format(fmt)
        self.sweep = sweep
        self.out = Path(out)
        self.digest = sweep.digest(fmt)
        self.width = max(5, len(str(sweep.chunks - 1)))
        manifest = self.out / MANIFEST
        writable_dir("out", self.out)  # ValueError (one line) when it cannot be written
        if manifest.exists():
            self._check(json.loads(manifest.read_text(encoding="utf-8")))
        else:
            if any(self.out.iterdir()):
                raise ValueError(
                    f"{self.out} exists and holds no sweep ({MANIFEST} missing): "
                    "give a new or empty directory"
                )
            (self.out / "chunks").mkdir(parents=True, exist_ok=True)
            _write_atomic(manifest, _json_bytes(self._manifest()))
        self.chunk_dir.mkdir(exist_ok=True)
        for stale in self.chunk_dir.glob(".*.tmp"):  # a chunk cut off mid-write
            stale.unlink()

    @property
    def chunk_dir(self) -> Path:
        return self.out / "chunks"

    def _manifest(self) -> dict:
        described = self.sweep.described()
        return {
            "slipmaps_sweep": VERSION,
            "sha256": self.digest,
            "format": self.fmt,
            "rows": self.sweep.rows,
            "chunks": self.sweep.chunks,
            "chunk_rows": self.sweep.chunk_rows,
            "chunk_files": f"chunks/part-{{index:0{self.width}d}}.{self.fmt}",
            "definition": self.sweep.as_dict(),
            "columns": list(self.sweep.columns),
            "units": {k: v["unit"] for k, v in described.items()},
            "docs": {k: v["doc"] for k, v in described.items()},
        }

    def _check(self, found: dict) -> None:
        if found.get("sha256") == self.digest:
            return
        mine = {**self.sweep.as_dict(), "format": self.fmt}
        theirs = {**found.get("definition", {}), "format": found.get("format")}
        differ = sorted(k for k in set(mine) | set(theirs) if mine.get(k) != theirs.get(k))
        raise ValueError(
            f"{self.out} holds a different sweep (it differs in {', '.join(differ) or 'its hash'}): "
            "resume it with its own definition, or give another directory"
        )

    def path(self, index: int) -> Path:
        return self.chunk_dir / f"part-{index:0{self.width}d}.{self.fmt}"

    def done(self) -> dict[int, dict]:
        """The chunks already written: index -> {"rows": n, "counts": {status name: rows}}."""
        out = {}
        with os.scandir(self.chunk_dir) as entries:  # the files written, not every chunk's name
            names = [e.name for e in entries]
        for name in names:
            number = name.removeprefix("part-").removesuffix(f".{self.fmt}")
            if (
                not number.isdigit()
                or int(number) >= self.sweep.chunks
                or name != self.path(int(number)).name
            ):
                continue
            i = int(number)
            out[i] = json.loads(self.path(i).with_suffix(".json").read_text(encoding="utf-8"))
        return dict(sorted(out.items()))

    def write(self, index: int, payload: bytes, rows: int, counts: dict[str, int]) -> dict:
        """Chunk ``index`` (its file content): the counts first, then the data, each renamed in place."""
        record = {"index": index, "rows": rows, "counts": counts}
        _write_atomic(self.path(index).with_suffix(".json"), _json_bytes(record))
        _write_atomic(self.path(index), payload)
        return record

    def combine(self) -> Path:
        """``sweep.<fmt>``: every chunk in order in one file."""
        paths = [self.path(i) for i in range(self.sweep.chunks)]
        header = len(csv_header(self.sweep, self.digest)) if self.fmt == "csv" else 0
        return combine(paths, self.out / f"sweep.{self.fmt}", self.fmt, header)

    def write_summary(self, summary: dict) -> Path:
        path = self.out / "summary.json"
        _write_atomic(path, _json_bytes(summary))
        return path


def _chunk_paths(out: str | Path) -> list[Path]:
    out = Path(out)
    try:
        manifest = json.loads((out / MANIFEST).read_text(encoding="utf-8"))
    except OSError:
        raise ValueError(f"{out} is not a sweep directory ({MANIFEST} missing)") from None
    pattern = manifest["chunk_files"]
    return [p for i in range(manifest["chunks"]) if (p := out / pattern.format(index=i)).exists()]


def iter_sweep(out: str | Path, columns: Sequence[str] | None = None) -> Iterator[dict[str, np.ndarray]]:
    """The written chunks of the sweep in ``out``, in row order, one dict of columns at a time
    (``columns``: only these)."""
    for p in _chunk_paths(out):
        yield read(p, columns)[0]


def read_sweep(out: str | Path, *, frame: bool = False):
    """Every written row of the sweep in ``out`` as one dict of columns (in memory: for sweeps that
    fit; :func:`iter_sweep` streams); ``frame=True``: as a pandas DataFrame (the optional extra
    ``[pandas]``)."""
    parts = list(iter_sweep(out))
    if not parts:
        raise ValueError(f"{out}: no chunk written yet")
    columns = {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}
    return to_pandas(columns) if frame else columns
