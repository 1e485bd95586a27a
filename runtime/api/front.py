"""The cost-accuracy front as last measured: which map at its defaults another variant dominates.

``pareto.json`` (next to this module, shipped with the package) is written by
``benchmarks/bench_pareto.py`` (its full run; never by hand): per variant (a map with options) its
cost per apex return on one thread, its mean and max next-apex error against the exact map at its
default rtol 1e-11 on each of two grids of the accuracy study, its failures, and the cheapest
variant that dominates it (a map requiring nothing more, no more costly, no larger mean error, max
error or failures on either grid, better in one). ``slipmaps maps`` shows it per map; the errors
are checked against a re-computation by tests/test_front.py (the times are the benchmark's only:
no timing in the tests).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from importlib import resources

import numpy as np

__all__ = [
    "FRONT_FILE",
    "Variant",
    "at_defaults",
    "dominated_by",
    "errors_on",
    "front",
    "measurement",
]

#: The measured front's file, beside this module (package data).
FRONT_FILE = "pareto.json"


@dataclass(frozen=True)
class Variant:
    """One measured variant: a map with options (empty: its defaults)."""

    label: str
    map: str
    options: dict
    ns_per_apex_return: float
    mean_error: float
    max_error: float
    failures: int
    #: The label of the cheapest variant dominating this one, None on the front.
    dominated_by: str | None

    @property
    def default(self) -> bool:
        return not self.options

    @property
    def command(self) -> str:
        """The variant as the command line gives it: ``--map NAME [--option name=value ...]``."""
        return " ".join([f"--map {self.map}", *(f"--option {k}={v:g}" for k, v in self.options.items())])


def errors_on(got: Mapping, ref: Mapping) -> dict:
    """The accuracy study's next-apex error |(dh, dv)| / |(h, v)| of a batch result ``got`` against
    ``ref`` (``apex_return_batch`` results on the same states): mean and max over the states where
    both complete the step, and the failures (``got`` fails where ``ref`` does not)."""
    both = (got["status"] == 0) & (ref["status"] == 0)
    dh = got["next_apex_height"] - ref["next_apex_height"]
    dv = got["next_apex_speed"] - ref["next_apex_speed"]
    err = (np.hypot(dh, dv) / np.hypot(ref["next_apex_height"], ref["next_apex_speed"]))[both]
    return {
        "mean_error": float(err.mean()) if err.size else math.nan,
        "max_error": float(err.max()) if err.size else math.nan,
        "compared": int(err.size),
        "failures": int(((got["status"] != 0) & (ref["status"] == 0)).sum()),
    }


_MEASURES = ("mean_error", "max_error", "failures")
#: Errors within this relative difference are the same error (round-off: two maps that reduce to one
#: another on a grid differ in their last bits, which must not decide which is on the front).
TIE = 1e-9


def _no_worse(a: Mapping, b: Mapping) -> bool:
    return all(a[k] <= b[k] * (1.0 + TIE) for k in _MEASURES)


def _better(a: Mapping, b: Mapping) -> bool:
    return any(a[k] < b[k] * (1.0 - TIE) for k in _MEASURES)


def _covers(o: Mapping, r: Mapping) -> bool:
    """Whether o's map runs wherever r's does: it requires nothing r does not (``geyer`` requires
    constant stiffness, so it cannot stand in for ``geyer-vs``, whatever it costs on these grids)."""
    return set(o.get("requires", ())) <= set(r.get("requires", ()))


def dominated_by(rows: Sequence[Mapping]) -> list[str | None]:
    """Per row (``label``, ``ns_1_thread``, ``requires``: its map's, ``by_grid``: one
    :func:`errors_on` per grid), the label of the cheapest other row that dominates it: its map
    requires nothing this one does not, no more costly, no larger mean error, max error or failures
    on any grid (to :data:`TIE`), and cheaper or better in one of them; None when none does."""
    out = []
    for r in rows:
        doms = [
            o
            for o in rows
            if o is not r
            and _covers(o, r)
            and o["ns_1_thread"] <= r["ns_1_thread"]
            and all(_no_worse(a, b) for a, b in zip(o["by_grid"], r["by_grid"], strict=True))
            and (
                o["ns_1_thread"] < r["ns_1_thread"]
                or any(_better(a, b) for a, b in zip(o["by_grid"], r["by_grid"], strict=True))
            )
        ]
        out.append(min(doms, key=lambda o: o["ns_1_thread"])["label"] if doms else None)
    return out


@cache
def measurement() -> dict:
    """The whole file: the machine, the grids and every variant's row (bench_pareto.py's JSON)."""
    return json.loads(resources.files(__package__).joinpath(FRONT_FILE).read_text())


@cache
def front() -> dict[str, Variant]:
    """Every measured variant by label."""
    return {
        r["label"]: Variant(
            label=r["label"],
            map=r["map"],
            options=dict(r["options"]),
            ns_per_apex_return=float(r["ns_1_thread"]),
            mean_error=float(r["mean_error"]),
            max_error=float(r["max_error"]),
            failures=int(r["failures"]),
            dominated_by=r["dominated_by"],
        )
        for r in measurement()["rows"]
    }


def at_defaults(map_name: str) -> Variant | None:
    """The measured variant of ``map_name`` at its defaults (None: not measured, e.g. a half)."""
    return next((v for v in front().values() if v.map == map_name and v.default), None)
