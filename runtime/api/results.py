"""One result family for every map, exact or approximate: values by name, a status per row.

The names are the generated index's (``slipmaps.generated.maps_index``) as the API names them
(:mod:`.names`): a stance result has ``t_bottom``, ``t_stance``, ``bottom_q_r`` ... ``liftoff_q_thd``
(groups ``bottom`` and ``liftoff`` give the four together) plus the map's extras; an apex-return
result has ``next_apex_height``, ``next_apex_speed`` (the next apex), ``t_descent``, ``t_stance``,
``t_ascent`` and the ``liftoff`` group, and its ``inputs`` the apex it starts from
(``apex_height``, ``apex_speed``), ``touchdown_angle``, ``ground``, ``retraction_rate``. Values
are NaN wherever the status is not OK.

- :class:`Result`: one call. ``res["next_apex_height"]``, ``res.next_apex_height``, ``res.liftoff``
  (a tuple), ``res.status`` (:class:`~slipmaps.generated.status.Status`), ``res.message``,
  ``res.ok``, ``res.inputs``.
- :class:`BatchResult`: many rows. ``res["next_apex_height"]`` is an array (a view, no copy) in the
  shape of the inputs, ``res["liftoff"]`` has a trailing axis of 4, ``res["status"]`` the int64
  codes, ``res.ok`` a mask, ``res.counts()`` the rows per status, ``res.message(i)`` one row's
  message, ``res.inputs`` the inputs in that shape; ``columns()`` / ``to_pandas()`` a row per
  point: the inputs, the outputs, the status.

The former names of the next apex (``apex_height``, ``apex_speed``) still read, with a
DeprecationWarning (:mod:`.names`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
from slipmaps.generated import maps_index
from slipmaps.generated.status import MESSAGES, Status

from .frames import status_columns, to_arrow, to_pandas
from .names import RENAMED, public_names, warn_renamed

__all__ = ["Result", "BatchResult", "STANCE", "APEX_RETURN", "HALF", "GROUPS", "columns"]

#: Output names of every stance map and of every apex-return map (before a map's extras; public
#: names, :mod:`.names`).
STANCE = public_names(tuple(r["name"] for r in maps_index.STANCE_OUTPUTS))
APEX_RETURN = public_names(tuple(r["name"] for r in maps_index.APEX_OUTPUTS))
#: Output names of every half-stance map: ``t_half`` and the ``end`` state.
HALF = public_names(tuple(r["name"] for r in maps_index.HALF_OUTPUTS))
#: Named groups of outputs: "bottom" -> ("bottom_q_r", ..., "bottom_q_thd"), "liftoff" -> ...
GROUPS: dict[str, tuple[str, ...]] = {k: tuple(v) for k, v in maps_index.GROUPS.items()}


def columns(kind: str, extras: tuple[str, ...] = ()) -> tuple[str, ...]:
    """The output names of a ``"stance"``, ``"apex_return"`` or ``"half"`` result with a map's extras."""
    return {"stance": STANCE, "apex_return": APEX_RETURN, "half": HALF}[kind] + tuple(extras)


_WHERE = {"stance": "a stance result", "apex_return": "an apex-return result", "half": "a half-stance result"}


def renamed(name: str, have, kind: str, stacklevel: int) -> str | None:
    """The new name of a former name ``name`` that ``have`` holds (a warning, :mod:`.names`), or
    None; ``stacklevel`` counted from the caller."""
    new = RENAMED.get(name) if isinstance(name, str) else None
    if new is None or new not in have:
        return None
    warn_renamed(name, new, _WHERE.get(kind, f"a {kind} result"), stacklevel + 1)
    return new


@dataclass(frozen=True)
class Result:
    """The outcome of one map call (values NaN unless ``status`` is OK)."""

    map: str
    kind: str  # "stance", "apex_return" or "half"
    status: Status
    message: str
    values: Mapping[str, float]
    inputs: Mapping[str, object] = field(default_factory=dict)

    @classmethod
    def of(
        cls, map: str, kind: str, status: Status, message: str, values: Mapping, inputs: Mapping
    ) -> Result:
        """``Result(map, kind, status, message, values, inputs)`` in a third of the time: the frozen
        dataclass's ``__init__`` sets each field through ``object.__setattr__`` (0.9 us a result; a
        scalar call makes one)."""
        result = object.__new__(cls)
        result.__dict__.update(
            map=map, kind=kind, status=status, message=message, values=values, inputs=inputs
        )
        return result

    @property
    def ok(self) -> bool:
        return self.status == Status.OK

    def __getitem__(self, name: str):
        return self._get(name, 2)

    def _get(self, name: str, stacklevel: int):
        if name in self.values:
            return self.values[name]
        if name in GROUPS and all(n in self.values for n in GROUPS[name]):
            return tuple(self.values[n] for n in GROUPS[name])
        new = renamed(name, self.values, self.kind, stacklevel + 1)
        if new is not None:
            return self.values[new]
        raise KeyError(
            f"{self.kind} result of map {self.map!r} has no {name!r}; it has {', '.join(self.keys())}"
        )

    def __getattr__(self, name: str):
        if name.startswith("_") or name in ("values", "map", "kind", "status", "message", "inputs"):
            raise AttributeError(name)
        try:
            return self._get(name, 2)
        except KeyError as exc:
            raise AttributeError(str(exc)) from None

    def keys(self) -> tuple[str, ...]:
        groups = tuple(g for g, ns in GROUPS.items() if all(n in self.values for n in ns))
        return tuple(self.values) + groups

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self.keys()))

    def as_dict(self) -> dict:
        """JSON-ready: status name, message, values (None for NaN), inputs."""
        return {
            "map": self.map,
            "status": self.status.name,
            "message": self.message,
            "values": {k: (v if math.isfinite(v) else None) for k, v in self.values.items()},
            "inputs": dict(self.inputs),
        }


@lru_cache(maxsize=64)
def _column_index(names: tuple[str, ...]) -> dict[str, int]:
    return {n: j for j, n in enumerate(names)}


class BatchResult(Mapping):
    """The outcome of a batch call: one column per output, one status per row, and the inputs."""

    def __init__(
        self,
        map_name: str,
        kind: str,
        names: tuple[str, ...],
        data: np.ndarray,
        status: np.ndarray,
        shape,
        inputs: Mapping[str, object] | None = None,
    ):
        self.map = map_name
        self.kind = kind
        self.names = tuple(names)
        self.shape = tuple(shape)
        self._index = _column_index(self.names)
        self._data = data  # (n, len(names)), NaN rows where status != 0
        self._status = status
        # by public name, as given (not copied): a number, or an array (or list) broadcasting to shape
        self._inputs = {} if inputs is None else inputs

    @property
    def status(self) -> np.ndarray:
        """int64 status codes (:class:`~slipmaps.generated.status.Status`), in the input shape."""
        return self._status.reshape(self.shape)

    @property
    def ok(self) -> np.ndarray:
        return self.status == int(Status.OK)

    @property
    def inputs(self) -> dict[str, np.ndarray]:
        """The per-row inputs by name, each in the input shape (read-only views of the arguments,
        broadcast): an apex-return batch's ``apex_height``, ``apex_speed``, ``touchdown_angle``,
        ``ground``, ``retraction_rate``; a stance batch's touchdown state ``q_r_td`` ...
        ``q_thd_td``; a half-stance batch's start state."""
        return {k: np.broadcast_to(np.asarray(v, dtype=float), self.shape) for k, v in self._inputs.items()}

    def __len__(self) -> int:
        return len(self.names) + 1

    def __iter__(self) -> Iterator[str]:
        yield from self.names
        yield "status"

    def __contains__(self, name) -> bool:
        return (
            name == "status"
            or name in self._index
            or (name in GROUPS and all(n in self._index for n in GROUPS[name]))
        )

    def __getitem__(self, name: str) -> np.ndarray:
        if name == "status":
            return self.status
        if name in self._index:
            return self._data[:, self._index[name]].reshape(self.shape)
        if name in GROUPS and all(n in self._index for n in GROUPS[name]):
            j = self._index[GROUPS[name][0]]
            return self._data[:, j : j + len(GROUPS[name])].reshape(*self.shape, len(GROUPS[name]))
        new = renamed(name, self._index, self.kind, 2)
        if new is not None:
            return self._data[:, self._index[new]].reshape(self.shape)
        raise KeyError(
            f"{self.kind} batch of map {self.map!r} has no column {name!r}; it has {', '.join(self)}"
        )

    def message(self, i) -> str:
        """The message of row ``i`` (an index into the input shape)."""
        return MESSAGES[int(self.status[i])]

    def counts(self) -> dict[str, int]:
        """Rows per status name, most common first."""
        codes, counts = np.unique(self._status, return_counts=True)
        order = np.argsort(-counts, kind="stable")
        return {Status(int(codes[i])).name: int(counts[i]) for i in order}

    def columns(self) -> dict[str, np.ndarray]:
        """A 1-D column per input, per output and the status (name and code), a row per point in C
        order of the input shape (``slipmaps.runtime.api.frames``)."""
        out = {k: v.reshape(-1) for k, v in self.inputs.items()}
        out |= {n: self._data[:, j] for n, j in self._index.items()}
        return out | status_columns(self._status)

    def to_pandas(self):
        """A pandas DataFrame of :meth:`columns` (pandas is the optional extra ``[pandas]``)."""
        return to_pandas(self.columns())

    def to_arrow(self):
        """A pyarrow Table of :meth:`columns`."""
        return to_arrow(self.columns())

    def __repr__(self) -> str:
        return (
            f"BatchResult(map={self.map!r}, kind={self.kind!r}, shape={self.shape}, status={self.counts()})"
        )
