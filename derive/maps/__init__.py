"""One module per map (or family of maps): its derivation steps and its declarations, ``MAPS``.

:func:`all_maps` finds every module of this package that declares ``MAPS`` (a tuple of
:class:`~slipmaps.derive.mapspec.MapSpec`), so adding a map is adding its module; the maps are
ordered by report section, then name.
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import cache


def _section_key(section: str) -> tuple[int, ...]:
    return tuple(int(p) for p in section.split("."))


@cache
def all_maps():
    """Every declared map, in report order (section, then name)."""
    specs = []
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name):
        module = importlib.import_module(f"{__name__}.{info.name}")
        specs.extend(getattr(module, "MAPS", ()))
    names = [s.name for s in specs]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ValueError(f"map name(s) declared twice: {dup}")
    return tuple(sorted(specs, key=lambda s: (_section_key(s.section), s.name)))
