"""Parameter sweeps: any map (and ``"exact"``) over a grid or a random sample, written chunk by chunk.

::

    import slipmaps

    sw = slipmaps.Sweep(
        "gravity-type5",
        axes={"apex_speed": {"low": 3.0, "high": 7.0, "num": 81}, "touchdown_angle": [0.30, 0.35, 0.40]},
        fixed={"apex_height": 1.0},
        params=slipmaps.HUMAN_RUNNER,
    )
    summary = slipmaps.sweep(sw, "out/type5", format="parquet")   # or scheduler="local:2"
    summary.counts, slipmaps.read_sweep("out/type5")["next_apex_height"]

or from a TOML file (``examples/sweep.toml``; its ``out``, ``format``, ``scheduler`` and ``combine``
are the defaults of the arguments): ``slipmaps.sweep("examples/sweep.toml")``; on the command line
``slipmaps sweep examples/sweep.toml``.

The rows are :func:`slipmaps.apex_return_batch` (``kind="apex_return"``) or
:func:`slipmaps.stance_batch` (``kind="stance"``) rows, chunk by chunk (:mod:`.compute`); the
quantities, units and row order are :mod:`.axes`'s, the definition :mod:`.spec`'s, the
files :mod:`.files`'s and the directory layout and resuming :mod:`.store`'s; where the
chunks run is :mod:`.schedulers`'s. Memory holds a few chunks, never the whole sweep: a grid
point is computed from its row index. Running the same sweep into the same directory again
resumes it: the chunks already written are kept, the others computed.
"""

from __future__ import annotations

import itertools
import time
from collections import Counter
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path

from ..api.progress import Bar
from .schedulers import check_scheduler, run_chunks
from .spec import DEFINITION_KEYS, Sweep, read_toml
from .store import Store, iter_sweep, read_sweep

__all__ = [
    "Sweep",
    "SweepSummary",
    "sweep",
    "load",
    "split_keys",
    "read_sweep",
    "iter_sweep",
    "RUN_KEYS",
    "KEYS",
]

#: The keys of a sweep TOML file that say how to run it, not what it is.
RUN_KEYS = ("out", "format", "scheduler", "combine")


@dataclass(frozen=True)
class SweepSummary:
    """What a :func:`sweep` call left in ``out``."""

    out: Path
    map: str
    rows: int  # rows of the sweep
    rows_done: int  # rows written (now or before)
    counts: dict[str, int]  # rows written per status name, most first
    chunks: int
    chunks_done: int
    chunks_new: int  # chunks computed by this call
    rows_new: int
    seconds: float  # this call's wall time
    combined: Path | None = None

    @property
    def complete(self) -> bool:
        return self.chunks_done == self.chunks

    @property
    def rows_ok(self) -> int:
        return self.counts.get("OK", 0)

    @property
    def rate(self) -> float:
        """Rows per second computed and written by this call."""
        return self.rows_new / self.seconds if self.seconds > 0 else float("nan")

    def as_dict(self) -> dict:
        return {
            "out": str(self.out),
            "map": self.map,
            "rows": self.rows,
            "rows_done": self.rows_done,
            "rows_ok": self.rows_ok,
            "counts": dict(self.counts),
            "chunks": self.chunks,
            "chunks_done": self.chunks_done,
            "complete": self.complete,
            "combined": None if self.combined is None else str(self.combined),
        }

    def format(self) -> str:
        """A few lines for a terminal."""
        pct = 100.0 * self.rows_ok / self.rows_done if self.rows_done else 0.0
        state = "complete" if self.complete else f"{self.chunks_done} of {self.chunks} chunks written"
        lines = [
            f"sweep of {self.map}: {self.rows_done} of {self.rows} rows ({state}), "
            f"{self.rows_ok} OK ({pct:.1f} %)",
            "  rows by status: " + ", ".join(f"{k} {v}" for k, v in self.counts.items()),
            f"  this run: {self.chunks_new} chunk{'' if self.chunks_new == 1 else 's'}, "
            f"{self.rows_new} rows in {self.seconds:.2f} s"
            + (f" ({self.rate:.3g} rows/s)" if self.rows_new else ""),
            f"  written to {self.out}/" + (f" (all rows: {self.combined})" if self.combined else ""),
        ]
        if not self.complete:
            lines.append("  run the same sweep into the same directory again to resume")
        return "\n".join(lines)


#: Every top-level key of a sweep TOML file (or mapping): the definition's, then how to run it.
KEYS = (*DEFINITION_KEYS, *RUN_KEYS)


def split_keys(data: Mapping[str, object], where: str = "sweep") -> tuple[dict, dict]:
    """A sweep file's (or mapping's) top-level keys -> (the definition's keys, the run settings of
    :data:`RUN_KEYS`); ValueError naming ``where`` and listing every accepted key (:data:`KEYS`)
    for a key that is neither."""
    unknown = set(data) - set(KEYS)
    if unknown:
        raise ValueError(
            f"{where}: unknown key(s) {', '.join(sorted(unknown))}; the keys are {', '.join(KEYS)}"
        )
    definition = dict(data)
    run = {k: definition.pop(k) for k in RUN_KEYS if k in definition}
    return definition, run


def load(path: str | Path, overrides: Mapping[str, object] | None = None) -> tuple[Sweep, dict]:
    """A sweep TOML file -> (the sweep, its run settings :data:`RUN_KEYS`); ``overrides`` replace
    top-level keys of the file (the command line's flags)."""
    data = dict(read_toml(path))
    data.update(overrides or {})
    definition, run = split_keys(data, str(path))
    return Sweep.from_dict(definition), run


def sweep(
    definition: Sweep | Mapping | str | Path,
    out: str | Path | None = None,
    *,
    format: str | None = None,
    scheduler=None,
    progress: bool | None = None,
    combine: bool | None = None,
    max_chunks: int | None = None,
    on_chunk: Callable[[int], None] | None = None,
) -> SweepSummary:
    """Run ``definition`` (a :class:`Sweep`, a mapping of its keys, or a TOML file) into directory
    ``out``, resuming what is already there.

    ``format``: "csv" (default) or "parquet" (needs pyarrow). ``scheduler``: None / "inprocess"
    (default), "local:N" or a dask address / Client (``slipmaps.runtime.sweep.schedulers``).
    ``progress``: a bar on standard error (None: on a terminal, after a second). ``combine``: also
    write all rows to ``out/sweep.<format>`` once every chunk is written. ``max_chunks``: compute at
    most this many chunks in this call (the rest on a later call). ``on_chunk(index)``: called after
    each chunk is written. ValueError for a bad definition or directory, before anything is computed.
    """
    run: dict = {}
    if isinstance(definition, (str, Path)):
        definition, run = load(definition)
    elif isinstance(definition, Mapping):
        data, run = split_keys(definition)
        definition = Sweep.from_dict(data)
    elif not isinstance(definition, Sweep):
        raise TypeError(
            f"definition must be a Sweep, a mapping or a TOML path, got {type(definition).__name__}"
        )
    out = out if out is not None else run.get("out")
    if out is None:
        raise ValueError("a sweep needs an output directory (out)")
    fmt = format or run.get("format", "csv")
    scheduler = check_scheduler(scheduler if scheduler is not None else run.get("scheduler"))
    combine = bool(run.get("combine", False) if combine is None else combine)
    if max_chunks is not None and (
        isinstance(max_chunks, bool) or int(max_chunks) != max_chunks or max_chunks < 0
    ):
        raise ValueError(f"max_chunks must be a non-negative whole number, got {max_chunks!r}")

    t0 = time.perf_counter()
    store = Store(out, definition, fmt)
    done = store.done()
    todo = (i for i in range(definition.chunks) if i not in done)  # lazily: 10^11 rows are 10^6 chunks
    if max_chunks is not None:
        todo = itertools.islice(todo, int(max_chunks))
    counts = Counter()
    for rec in done.values():
        counts.update(rec["counts"])
    rows_before = sum(rec["rows"] for rec in done.values())
    new_rows = new_chunks = 0
    label = f"sweep {definition.map}"
    with Bar(definition.rows, label, progress, initial=rows_before, unit="rows") as bar:
        for cf in run_chunks(definition, fmt, store.digest, todo, scheduler):
            done[cf.index] = store.write(cf.index, cf.payload, cf.rows, cf.counts)
            counts.update(cf.counts)
            new_rows += cf.rows
            new_chunks += 1
            bar.update(cf.rows)
            if on_chunk is not None:
                on_chunk(cf.index)
    complete = len(done) == definition.chunks
    combined = store.combine() if complete and combine else None
    summary = SweepSummary(
        out=store.out,
        map=definition.map,
        rows=definition.rows,
        rows_done=rows_before + new_rows,
        counts=dict(counts.most_common()),
        chunks=definition.chunks,
        chunks_done=len(done),
        chunks_new=new_chunks,
        rows_new=new_rows,
        seconds=time.perf_counter() - t0,
        combined=combined,
    )
    if complete:
        store.write_summary(summary.as_dict())
    return summary
