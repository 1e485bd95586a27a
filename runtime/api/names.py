"""The public names of the results' values, declared once: an output named like an input of the map
is the next value of that input, ``next_<name>``.

The apex-return kernels write the next apex as ``apex_height`` and ``apex_speed`` (the generated
index's output names, ``slipmaps.generated.maps_index.APEX_OUTPUTS``), the names of two of the
map's inputs (derive/params.py, ``APEX_INPUTS``). Every result of the API calls the next apex
``next_apex_height``, ``next_apex_speed`` and the apex it starts from ``apex_height``,
``apex_speed``: :func:`slipmaps.apex_return` and its batch (values, ``inputs``, tables), the
Jacobians' rows, :func:`slipmaps.deadbeat` and its batch, the bottom stage, swing policies, runs
and sweeps. :data:`RENAMED` is the rule of derive/params.py (``public_output``: a kernel output
named like an input -> ``next_`` + its name) applied to the index; :func:`public` reads it. The
kernels, the generated index and the studies' stored records (docs/*.json) keep the kernel names.

The former names still read, for now: ``res.apex_height``, ``batch["apex_speed"]``,
``jac["apex_height", "touchdown_angle"]``, a deadbeat result's ``apex_height``, a run's
``next_height`` / ``next_speed`` give the next apex with a :class:`DeprecationWarning` naming the
new name (:func:`warn_renamed`, :class:`Renamed`, :class:`RenamedKeys`). They go in slipmaps
:data:`REMOVED_IN`; from then ``apex_height`` and ``apex_speed`` name the input apex only.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from functools import lru_cache

from slipmaps.derive import params as _table
from slipmaps.generated import maps_index

__all__ = [
    "INPUTS",
    "KERNEL_NAMES",
    "NEXT",
    "REMOVED_IN",
    "RENAMED",
    "RUN_RENAMED",
    "Renamed",
    "RenamedKeys",
    "kernel_name",
    "public",
    "public_names",
    "warn_renamed",
]

#: The prefix of an output that is the next value of an input (derive/params.py).
NEXT = _table.NEXT
#: The apex-return inputs' public names (derive/params.py), in the table's order.
INPUTS: tuple[str, ...] = tuple(r["name"] for r in _table.APEX_INPUTS)
#: Kernel output name -> public name, for every output named like an input (derive/params.py,
#: ``public_output``): ``apex_height`` -> ``next_apex_height``, ``apex_speed`` -> ``next_apex_speed``.
RENAMED: dict[str, str] = {
    r["name"]: _table.public_output(r["name"])
    for r in maps_index.APEX_OUTPUTS
    if _table.public_output(r["name"]) != r["name"]
}
#: Public name -> kernel output name (the inverse of :data:`RENAMED`).
KERNEL_NAMES: dict[str, str] = {new: old for old, new in RENAMED.items()}
#: A run's and a swing policy's former names of the next apex (``next_height`` ...) -> the public one.
RUN_RENAMED: dict[str, str] = {NEXT + old.removeprefix("apex_"): new for old, new in RENAMED.items()}
#: The release that removes the former names (docs/changelog.md).
REMOVED_IN = "0.3.0"


def public(name: str) -> str:
    """The public name of a kernel output (itself unless :data:`RENAMED`)."""
    return RENAMED.get(name, name)


def kernel_name(name: str) -> str:
    """The kernel output name of a public name (itself unless renamed)."""
    return KERNEL_NAMES.get(name, name)


@lru_cache(maxsize=256)
def public_names(names: tuple[str, ...]) -> tuple[str, ...]:
    """The public names of a kernel's outputs, in their order."""
    return tuple(RENAMED.get(n, n) for n in names)


def warn_renamed(old: str, new: str, where: str, stacklevel: int = 2) -> None:
    """The :class:`DeprecationWarning` of a former name ``old`` read on ``where`` (e.g. "an
    apex-return result"); ``stacklevel`` as :func:`warnings.warn`'s, counted from the caller."""
    note = " (the next apex; 'apex_height' and 'apex_speed' name the input apex)" if old in RENAMED else ""
    warnings.warn(
        f"slipmaps renamed {old!r} of {where} to {new!r}{note}; the old name goes in slipmaps {REMOVED_IN}",
        DeprecationWarning,
        stacklevel=stacklevel + 1,
    )


class Renamed:
    """A former attribute name on a class: reading it warns (:func:`warn_renamed`) and gives the
    attribute ``new``."""

    def __init__(self, new: str, where: str):
        self.new, self.where, self.old = new, where, new
        self.__doc__ = f"The former name of ``{new}`` (reading it warns; it goes in slipmaps {REMOVED_IN})."

    def __set_name__(self, owner, name: str) -> None:
        self.old = name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        warn_renamed(self.old, self.new, self.where)
        return getattr(obj, self.new)


class RenamedKeys(dict):
    """A dict whose former keys (``renamed``: old -> new) still read, with the warning; they are
    not among its keys."""

    def __init__(self, values: Mapping, renamed: Mapping[str, str], where: str):
        super().__init__(values)
        self.renamed, self.where = renamed, where

    def __missing__(self, key):
        new = self.renamed.get(key) if isinstance(key, str) else None
        if new is None or new not in self:
            raise KeyError(key)
        warn_renamed(key, new, self.where)
        return self[new]

    def get(self, key, default=None):
        try:
            return self[key]
        except KeyError:
            return default
