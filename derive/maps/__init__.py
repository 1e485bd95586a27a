"""One module per map, named after it (``geyer_vs.py`` declares ``geyer-vs``), or per family of maps,
named after the family (``gravity.py`` declares ``gravity-type0`` ... ``gravity-type4``): its
derivation steps and its declarations, ``MAPS`` (and ``HALVES``, half-stance maps, beside the map
they are the halves of). A module that declares no map holds helpers and says so in its name
(``iterative_helpers.py``, ``quadrature_helpers.py``). :func:`all_maps` checks both rules: a map
(or half) lives in the module whose name is the longest prefix of its identifier.

:func:`all_maps` finds every module of this package that declares ``MAPS`` (a tuple of
:class:`~slipmaps.derive.mapspec.MapSpec`), :func:`all_halves` those that declare ``HALVES``
(:class:`~slipmaps.derive.halfspec.HalfSpec`), so adding a map is adding its module; the maps are
ordered by report section, then name.

A declaration that takes the other maps as a choice cannot be a tuple built at import: the
iterative maps start from a zeroth iterate that can be any map not itself iterated from one (their
option ``zeroth``). Such a module declares its maps and halves by functions, ``declare_maps()`` and
``declare_halves()``, called once every tuple is known. :func:`starting_maps` are the maps declared
as tuples: the maps a zeroth iterate can come from, so a new map is a zeroth-iterate choice of the
iterative maps with no edit elsewhere.
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import cache

__all__ = ["HELPERS_SUFFIX", "all_maps", "all_halves", "starting_maps"]

#: The name ending of a module that declares no map.
HELPERS_SUFFIX = "_helpers"


def _section_key(section: str) -> tuple[int, ...]:
    return tuple(int(p) for p in section.split("."))


def _ordered(specs) -> tuple:
    return tuple(sorted(specs, key=lambda s: (_section_key(s.section), s.name)))


@cache
def _modules():
    return tuple(
        importlib.import_module(f"{__name__}.{info.name}")
        for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name)
    )


def _short(module) -> str:
    return module.__name__.rsplit(".", 1)[-1]


#: The attributes a map module declares with: tuples, and the functions of a module whose
#: declarations take the other maps as a choice.
_TUPLES, _FUNCTIONS = ("MAPS", "HALVES"), ("declare_maps", "declare_halves")


def _tuples(attr: str) -> list[tuple[str, object]]:
    """(module name, declaration) of every module's tuple ``attr`` ("MAPS" or "HALVES")."""
    return [(_short(m), s) for m in _modules() for s in getattr(m, attr, ())]


def _declared(attr: str) -> list[tuple[str, object]]:
    """:func:`_tuples` of ``attr``, then what the modules' ``declare_maps()`` / ``declare_halves()``
    return (called once every tuple is known)."""
    function = _FUNCTIONS[_TUPLES.index(attr)]
    lazy = [(_short(m), s) for m in _modules() if hasattr(m, function) for s in getattr(m, function)()]
    return _tuples(attr) + lazy


def _check_layout(declared: list[tuple[str, object]], what: str) -> None:
    """Each declaration lives in the module named the longest prefix of its identifier; a module
    declares something or is named ``*_helpers``, never both."""
    names = [_short(m) for m in _modules()]
    for module, spec in declared:
        prefixes = [n for n in names if spec.ident == n or spec.ident.startswith(n + "_")]
        home = max(prefixes, key=len, default=None)
        if module != home or module.endswith(HELPERS_SUFFIX):
            raise ValueError(
                f"{what} {spec.name} is declared in derive/maps/{module}.py: it belongs in "
                f"derive/maps/{home or spec.ident}.py, the module named after the map or its family"
            )
    for m in _modules():
        declares = any(hasattr(m, a) for a in _TUPLES + _FUNCTIONS)
        if declares == _short(m).endswith(HELPERS_SUFFIX):
            raise ValueError(
                f"derive/maps/{_short(m)}.py: a module that declares no map is named *{HELPERS_SUFFIX}.py, "
                "and only such a module"
            )


def _unique(specs, what: str) -> None:
    names = [s.name for s in specs]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ValueError(f"{what} name(s) declared twice: {dup}")


@cache
def starting_maps():
    """The maps a zeroth iterate can come from: every map declared as a tuple ``MAPS`` (not itself
    iterated from a zeroth iterate, so not declared by ``declare_maps()``), in report order."""
    return _ordered(s for _, s in _tuples("MAPS"))


@cache
def all_halves():
    """Every declared half-stance map (``HALVES``, ``declare_halves()``), in report order (section,
    then name)."""
    declared = _declared("HALVES")
    _check_layout(declared, "half map")
    specs = [s for _, s in declared]
    _unique(specs + list(all_maps()), "map")
    return _ordered(specs)


@cache
def all_maps():
    """Every declared map (``MAPS``, ``declare_maps()``), in report order (section, then name)."""
    declared = _declared("MAPS")
    _check_layout(declared, "map")
    specs = [s for _, s in declared]
    _unique(specs, "map")
    return _ordered(specs)
