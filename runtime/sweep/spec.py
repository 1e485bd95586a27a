"""A sweep's definition: which map, which quantities vary (axes) and which are fixed, grid or random,
and how the rows fall into chunks; validated on construction, identified by a hash.

``Sweep(map, axes, fixed, params=..., kind=..., options=..., mode=..., samples=..., seed=...,
chunk_rows=...)``; ``Sweep.from_dict`` reads the same from a TOML table or JSON (:func:`read_toml`).
The quantities, their units and the row order are :mod:`.axes`'s. The parameters of a row are
``params`` (default the human runner), overridden by ``fixed``, overridden by the row's parameter
axes; ``k`` sets both stiffnesses, ``k_d_over_k_c`` sets ``k_d = k_c * ratio``; ``q_r_td`` and
``q_r_lo`` equal to ``l0`` in ``params`` follow a swept ``l0``. A row whose parameters are invalid
together (``q_r_td > l0``) gets ``INVALID_INPUT``, like any bad row of a batch; a value outside its
quantity's domain, an unknown name or a constant-stiffness map asked to vary one stiffness is a
ValueError here, before anything runs.

Output columns: the kind's inputs (all, fixed or not), the swept parameters, the batch API's
result names (the next apex ``next_apex_height``, ``next_apex_speed``: ``slipmaps.runtime.api.names``),
``status`` and ``status_name``.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from slipmaps.generated import maps_index

from ..api.files import read_toml
from ..api.index import EXACT, MapInfo, get, maps
from ..api.names import public
from ..api.params import HUMAN_RUNNER, SlipParams
from ..api.results import columns as result_columns
from .axes import (
    CHUNK_ROWS_EXACT,
    CHUNK_ROWS_GENERATED,
    KINDS,
    RATIO,
    Axis,
    Quantity,
    grid_points,
    quantities,
    random_points,
)

__all__ = ["Sweep", "MODES", "DEFINITION_KEYS", "axes_by_name", "read_toml"]

MODES = ("grid", "random")
#: The keys of a sweep definition (TOML / JSON).
DEFINITION_KEYS = ("map", "kind", "mode", "samples", "seed", "chunk_rows", "options", "fixed", "axes")
_STIFFNESS = ("k", "k_c", "k_d", RATIO)
_PLAIN_PARAMS = ("m", "l0", "g_s", "g_f", "q_r_td", "q_r_lo")


def _base_constants(params: SlipParams) -> dict[str, float]:
    """``params`` as sweep constants: ``k`` for a constant stiffness, leg lengths equal to l0 left
    out (so that they follow a swept l0)."""
    d = {"m": params.m, "l0": params.l0, "g_s": params.g_s, "g_f": params.g_f}
    if params.constant_stiffness:
        d["k"] = params.k_c
    else:
        d.update(k_c=params.k_c, k_d=params.k_d)
    for name in ("q_r_td", "q_r_lo"):
        if getattr(params, name) != params.l0:
            d[name] = getattr(params, name)
    return d


def _merge_stiffness(base: dict[str, float], given: set[str]) -> None:
    """Drop or expand ``base``'s stiffness entries for the ones the user gives (in place)."""
    if "k" in given and given & {"k_c", "k_d"}:
        raise ValueError("give either k (both stiffnesses) or k_c/k_d, not both")
    if RATIO in given and "k_d" in given:
        raise ValueError(f"give either k_d or {RATIO} (k_d = k_c * {RATIO}), not both")
    if "k" in given:
        for n in ("k_c", "k_d"):
            base.pop(n, None)
    if given & {"k_c", "k_d"} and "k" in base:
        base["k_c"] = base["k_d"] = base.pop("k")
    if RATIO in given:
        base.pop("k_d", None)


def _stiffnesses(values: Mapping[str, float]) -> tuple[float, float]:
    """(k_c, k_d) from merged values holding ``k`` or ``k_c``, and ``k_d`` or the ratio."""
    k_c = float(values["k"] if "k" in values else values["k_c"])
    if RATIO in values:
        return k_c, k_c * float(values[RATIO])
    return k_c, float(values["k"] if "k" in values else values["k_d"])


def slip_params(values: Mapping[str, float]) -> SlipParams:
    """The SlipParams of one row from its merged constants and parameter values (ValueError when
    they are invalid together)."""
    k_c, k_d = _stiffnesses(values)
    return SlipParams(k_c=k_c, k_d=k_d, **{n: float(values[n]) for n in _PLAIN_PARAMS if n in values})


def _whole(what: str, value: object, low: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise ValueError(f"{what} must be a whole number >= {low}, got {value!r}")
    return int(value)


def _check_names(kind: str, known: Mapping[str, Quantity], axes: Mapping, fixed: Mapping) -> None:
    """Every name a quantity of ``kind``, none both fixed and swept, every required input given."""
    for name in (*axes, *fixed):
        if name not in known:
            raise ValueError(
                f"unknown sweep quantity {name!r}; a sweep of kind {kind!r} varies or fixes: "
                + ", ".join(known)
            )
    both = set(axes) & set(fixed)
    if both:
        raise ValueError(f"{', '.join(sorted(both))}: both fixed and swept; choose one")
    missing = [q.name for q in KINDS[kind] if q.name not in axes and q.name not in fixed and not q.optional]
    if missing:
        raise ValueError(f"a sweep of kind {kind!r} needs {', '.join(missing)}: fix it or give it an axis")


def _check_params(info: MapInfo, constants: dict[str, float], axes: list[Axis]) -> None:
    """Refuse now what would fail every row: a constant-stiffness map asked to vary k_c, k_d or their
    ratio, or given a fixed ratio != 1; parameters the map refuses for the most favourable row (the
    shortest swept leg lengths, the longest swept l0, the low end of other axes)."""
    swept = {a.name: a for a in axes if a.name in _STIFFNESS or a.name in _PLAIN_PARAMS}
    if "constant_stiffness" in info.requires:
        varied = sorted(set(swept) & {"k_c", "k_d", RATIO})
        if varied:
            others = [m.name for m in maps() if "constant_stiffness" not in m.requires]
            raise ValueError(
                f"map {info.name!r} needs a constant leg stiffness (k_c == k_d) and cannot sweep "
                f"{', '.join(varied)}; sweep k instead, or a map that accepts k_c != k_d: "
                + ", ".join(others)
            )
    probe = {n: a.bounds()[1] if n == "l0" else a.bounds()[0] for n, a in swept.items()}
    info.check_params(slip_params({**constants, **probe}))


@dataclass(frozen=True, init=False)
class Sweep:
    """A validated sweep definition (see the module docstring); hashable, picklable, immutable."""

    map: str
    kind: str
    mode: str
    axes: tuple[Axis, ...]  # in row order: parameter axes, then input axes, each as declared
    fixed: tuple[tuple[str, float], ...]  # inputs, then the merged parameter constants
    options: tuple[tuple[str, object], ...]  # the map's resolved options
    samples: int | None
    seed: int
    chunk_rows: int

    def __init__(
        self,
        map: str,
        axes: Mapping[str, object],
        fixed: Mapping[str, float] | None = None,
        *,
        params: SlipParams = HUMAN_RUNNER,
        kind: str = "apex_return",
        options: Mapping[str, object] | None = None,
        mode: str = "grid",
        samples: int | None = None,
        seed: int = 0,
        chunk_rows: int | None = None,
    ) -> None:
        info = get(map)
        known = quantities(kind)
        if not isinstance(params, SlipParams):
            raise TypeError(f"params must be a SlipParams, got {type(params).__name__}: {params!r}")
        if not isinstance(axes, Mapping) or (fixed is not None and not isinstance(fixed, Mapping)):
            raise TypeError("axes and fixed must be mappings of quantity name -> axis / value")
        fixed = dict(fixed or {})
        _check_names(kind, known, axes, fixed)
        parsed = [Axis.of(n, spec) for n, spec in axes.items()]
        for a in parsed:
            a.check(known[a.name])
        values = {n: known[n].check(f"fixed {n}", v) for n, v in fixed.items()}
        inputs = KINDS[kind]
        input_names = {q.name for q in inputs}
        swept = {a.name for a in parsed}
        given_params = {n for n in (*axes, *fixed) if n not in input_names}
        constants = _base_constants(params)
        _merge_stiffness(constants, given_params)
        constants.update({n: v for n, v in values.items() if n not in input_names})
        for name in swept:
            constants.pop(name, None)
        _check_params(info, constants, [a for a in parsed if a.name not in input_names])

        resolved = info.resolve(dict(options or {}))
        info.encode(resolved)
        if mode not in MODES:
            raise ValueError(f"sweep mode must be one of {', '.join(repr(m) for m in MODES)}, got {mode!r}")
        if mode == "grid":
            if samples is not None:
                raise ValueError(
                    "samples is for a random sweep (mode = 'random'); a grid has one row per point"
                )
            for a in parsed:
                a.check_grid()  # ValueError for a range without num (nothing allocated)
        else:
            samples = _whole("a random sweep's samples", samples, 1)
        seed = _whole("seed", seed, 0)
        default_rows = CHUNK_ROWS_EXACT if info.name == EXACT else CHUNK_ROWS_GENERATED
        chunk_rows = _whole("chunk_rows", default_rows if chunk_rows is None else chunk_rows, 1)

        ordered = [a for a in parsed if a.name not in input_names] + [
            a for a in parsed if a.name in input_names
        ]
        fixed_items = [(q.name, values[q.name]) for q in inputs if q.name in values]
        fixed_items += [(n, float(constants[n])) for n in known if n in constants and n not in input_names]
        set_ = object.__setattr__
        set_(self, "map", info.name)
        set_(self, "kind", kind)
        set_(self, "mode", mode)
        set_(self, "axes", tuple(ordered))
        set_(self, "fixed", tuple(fixed_items))
        set_(self, "options", tuple(resolved.items()))
        set_(self, "samples", samples)
        set_(self, "seed", seed)
        set_(self, "chunk_rows", chunk_rows)
        if self.rows > 2**62:
            raise ValueError(f"the sweep has {self.rows} rows, more than 2**62")

    # -- construction from files ---------------------------------------------------------------
    @classmethod
    def from_dict(cls, d: Mapping[str, object]) -> Sweep:
        """A sweep from a TOML table / JSON object with the keys of :data:`DEFINITION_KEYS`."""
        unknown = set(d) - set(DEFINITION_KEYS)
        if unknown:
            raise ValueError(
                f"unknown sweep key(s) {', '.join(sorted(unknown))}; "
                f"the keys are {', '.join(DEFINITION_KEYS)}"
            )
        if "map" not in d:
            raise ValueError("a sweep needs map (a name of `slipmaps maps`)")
        kw = {k: d[k] for k in ("kind", "mode", "samples", "seed", "chunk_rows", "options") if k in d}
        return cls(d["map"], axes_by_name(d.get("axes", {})), d.get("fixed", {}), **kw)

    def as_dict(self) -> dict:
        """The canonical definition (what the hash covers): everything that decides the rows."""
        d = {
            "map": self.map,
            "kind": self.kind,
            "mode": self.mode,
            "options": dict(self.options),
            "fixed": dict(self.fixed),
            "axes": [{"name": a.name, **a.as_dict()} for a in self.axes],  # in row order
            "chunk_rows": self.chunk_rows,
        }
        if self.mode == "random":
            d.update(samples=self.samples, seed=self.seed)
        return d

    def digest(self, fmt: str) -> str:
        """sha256 of the canonical definition and the file format: a sweep directory's identity."""
        blob = json.dumps({"sweep": self.as_dict(), "format": fmt}, sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(blob.encode()).hexdigest()

    # -- rows and chunks -----------------------------------------------------------------------
    @property
    def rows(self) -> int:
        if self.mode == "random":
            return int(self.samples)
        return math.prod(a.grid_size for a in self.axes)

    @property
    def chunks(self) -> int:
        return -(-self.rows // self.chunk_rows)

    def chunk_bounds(self, i: int) -> tuple[int, int]:
        if not 0 <= i < self.chunks:
            raise ValueError(f"chunk {i} out of range: the sweep has {self.chunks} chunks")
        start = i * self.chunk_rows
        return start, min(start + self.chunk_rows, self.rows)

    def points(self, start: int, stop: int) -> dict[str, np.ndarray]:
        """The swept values of rows ``start..stop-1``, by axis name (``slipmaps.runtime.sweep.axes``)."""
        if not 0 <= start <= stop <= self.rows:
            raise ValueError(f"rows {start}..{stop} out of range 0..{self.rows}")
        if self.mode == "random":
            return random_points(self.axes, self.seed, start, stop)
        return grid_points(self.axes, start, stop)

    # -- columns -------------------------------------------------------------------------------
    @property
    def input_names(self) -> tuple[str, ...]:
        return tuple(q.name for q in KINDS[self.kind])

    @property
    def param_axes(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.axes if a.name not in self.input_names)

    @property
    def output_names(self) -> tuple[str, ...]:
        """The batch API's result names, in its order (the output columns)."""
        return result_columns(self.kind, get(self.map).extras)

    @property
    def columns(self) -> tuple[str, ...]:
        return (*self.input_names, *self.param_axes, *self.output_names, "status", "status_name")

    def described(self) -> dict[str, dict[str, str]]:
        """Each column's unit and description (SI; outputs from the generated index)."""
        known = quantities(self.kind)
        out = {n: {"unit": known[n].unit, "doc": known[n].doc} for n in (*self.input_names, *self.param_axes)}
        rows = {public(r["name"]): r for r in (*maps_index.STANCE_OUTPUTS, *maps_index.APEX_OUTPUTS)}
        row = next((r for r in maps_index.MAPS if r["name"] == self.map), None)
        rows.update({e["name"]: e for e in (row["extras"] if row else ())})
        for name in self.output_names:
            out[name] = {"unit": rows[name]["unit"], "doc": rows[name]["doc"]}
        out["status"] = {"unit": "", "doc": "status code (slipmaps.Status), 0 = OK"}
        out["status_name"] = {"unit": "", "doc": "status name (slipmaps.Status)"}
        return out


def axes_by_name(axes: object) -> object:
    """A definition's ``axes`` by quantity name: a mapping as it is, the canonical list form of
    :meth:`Sweep.as_dict` (``[{"name": ..., <axis>}, ...]``) as a dict; a name listed twice is a
    ValueError (two axes of one quantity contradict each other)."""
    if not isinstance(axes, list):
        return axes
    out = {}
    for a in axes:
        if not isinstance(a, Mapping) or "name" not in a:
            raise ValueError(f"axes as a list: each entry needs a name, got {a!r}")
        if a["name"] in out:
            raise ValueError(f"axis {a['name']!r} given twice in axes; give each quantity once")
        out[a["name"]] = {k: v for k, v in a.items() if k != "name"}
    return out
