"""One module per map (or family of maps): its derivation steps and its declarations, ``MAPS``
(and ``HALVES``, half-stance maps).

:func:`all_maps` finds every module of this package that declares ``MAPS`` (a tuple of
:class:`~slipmaps.derive.mapspec.MapSpec`), :func:`all_halves` those that declare ``HALVES``
(:class:`~slipmaps.derive.halfspec.HalfSpec`), so adding a map is adding its module; the maps are
ordered by report section, then name. The ground truth, the exact map (``exact.py``), is declared
the same way as :data:`GROUND_TRUTH` (:func:`ground_truth`), apart from the approximations.
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import cache


def _section_key(section: str) -> tuple[int, ...]:
    return tuple(int(p) for p in section.split("."))


@cache
def _modules():
    return tuple(
        importlib.import_module(f"{__name__}.{info.name}")
        for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name)
    )


def _unique(specs, what: str) -> None:
    names = [s.name for s in specs]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ValueError(f"{what} name(s) declared twice: {dup}")


@cache
def all_halves():
    """Every declared half-stance map (``HALVES``), in report order (section, then name)."""
    specs = [h for module in _modules() for h in getattr(module, "HALVES", ())]
    _unique(specs + list(all_maps()) + [ground_truth()], "map")
    return tuple(sorted(specs, key=lambda s: (_section_key(s.section), s.name)))


@cache
def ground_truth():
    """The exact map's declaration (the one module attribute ``GROUND_TRUTH``)."""
    (spec,) = [m.GROUND_TRUTH for m in _modules() if hasattr(m, "GROUND_TRUTH")]
    return spec


@cache
def all_maps():
    """Every declared map, in report order (section, then name)."""
    specs = [s for module in _modules() for s in getattr(module, "MAPS", ())]
    _unique(specs, "map")
    return tuple(sorted(specs, key=lambda s: (_section_key(s.section), s.name)))
