"""One module per map, named after it (``geyer_vs.py`` declares ``geyer-vs``), or per family of maps,
named after the family (``gravity.py`` declares ``gravity-type0`` ... ``gravity-type4``): its
derivation steps and its declarations, ``MAPS`` (and ``HALVES``, half-stance maps, beside the map
they are the halves of). A module that declares no map holds helpers and says so in its name
(``iterative_helpers.py``, ``quadrature_helpers.py``). :func:`all_maps` checks both rules: a map
(or half) lives in the module whose name is the longest prefix of its identifier.

:func:`all_maps` finds every module of this package that declares ``MAPS`` (a tuple of
:class:`~slipmaps.derive.mapspec.MapSpec`), :func:`all_halves` those that declare ``HALVES``
(:class:`~slipmaps.derive.halfspec.HalfSpec`), so adding a map is adding its module; the maps are
ordered by report section, then name. The ground truth, the exact map (``exact.py``), is declared
the same way as :data:`GROUND_TRUTH` (:func:`ground_truth`), apart from the approximations.

A declaration that takes the other maps as a choice cannot be a tuple built at import: the
iterative maps start from a zeroth iterate that can be any map not itself iterated from one (their
option ``zeroth``). Such a module declares its maps and halves by functions, ``declare_maps()`` and
``declare_halves()``, called once every tuple is known. :func:`starting_maps` are the maps declared
as tuples: the maps a zeroth iterate can come from, so a new map is a zeroth-iterate choice of the
iterative maps with no edit elsewhere.

Each map module's maps (and halves, and the ground truth) are documented on one family page,
``docs/<PAGE>.md``: the module attribute ``PAGE``, else the module's name (:func:`family_pages`).
``slipmaps generate`` writes the report equations of the page's maps into it.

What the studies of ``slipmaps accuracy`` and the command line do with a map, and which values of
its options they measure, is declared with it too: ``roles`` (:data:`MAP_ROLES`,
:data:`OPTION_ROLES`), published in the index, which is all the runtime reads.
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import cache

__all__ = [
    "HELPERS_SUFFIX",
    "MAP_ROLES",
    "OPTION_ROLES",
    "all_maps",
    "all_halves",
    "family_pages",
    "starting_maps",
]

#: The name ending of a module that declares no map.
HELPERS_SUFFIX = "_helpers"

#: The values of ``MapSpec.roles``: what the studies of ``slipmaps accuracy`` (runtime/studies/) and
#: the command line do with a map. They read the roles from the index; no map list is written there.
MAP_ROLES = {
    "baseline": "the accuracy study's reference: docs/accuracy.md's findings compare every map with it, "
    "and `slipmaps accuracy --map NAME` measures it beside NAME",
    "accuracy-figure": "a heatmap of docs/accuracy.png (next-apex error over apex speed and touchdown angle)",
    "yu-target": "held to the Yu, Li and Cai protocol target in docs/accuracy.md's findings (the best "
    "variant of these maps is named)",
    "region": "a panel of the self-stable region in docs/stability.png (beside the exact map), and of "
    "`slipmaps gait --figure` without --map",
    "default": "`slipmaps compare`'s map without --map: the first of these maps (report order) whose "
    "requirements the parameters meet",
}
#: The values of ``Option.roles``: which values of the option the studies measure. An option without
#: roles stays at its default in every study.
OPTION_ROLES = {
    "accuracy-variants": "docs/accuracy.md measures every value but the default once, the other options at "
    "their defaults (a choice's other choices, an integer's other whole numbers in [low, high])",
    "accuracy-passes": "the pass count of an iterated correction: docs/accuracy.md measures the map at one "
    "pass and at its fixed point (1 pass with the map's tolerance option at 0, 100 passes with it at "
    "1e-12)",
    "accuracy-readings": "docs/accuracy.md measures every value at one pass and at the fixed point of the "
    "map's accuracy-passes option",
    "convergence-passes": "the pass count docs/convergence.md varies, n = 0..8 (the tolerance option at 0: "
    "exactly n passes)",
    "convergence-series": "docs/convergence.md runs every value as a series of its own",
    "stiffness-variants": "docs/stiffness.md measures every value but the default once",
    "tolerance": "the stopping tolerance of the map's pass count (0: every pass runs), set by the studies "
    "with the passes",
}


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


def _declares(module) -> bool:
    """Whether ``module`` declares a map: a ``declare_*`` function, or a module attribute that is a
    declaration or a tuple of them (``MAPS``, ``HALVES``, or any other name)."""
    from ..halfspec import HalfSpec
    from ..mapspec import MapSpec

    def is_spec(value) -> bool:
        return isinstance(value, (MapSpec, HalfSpec))

    values = [v for k, v in vars(module).items() if not k.startswith("__")]
    return any(hasattr(module, f) for f in _FUNCTIONS) or any(
        is_spec(v) or (isinstance(v, tuple) and bool(v) and all(is_spec(x) for x in v)) for v in values
    )


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
        if _declares(m) == _short(m).endswith(HELPERS_SUFFIX):
            raise ValueError(
                f"derive/maps/{_short(m)}.py: a module that declares no map is named *{HELPERS_SUFFIX}.py, "
                "and only such a module"
            )


def _check_roles(specs) -> None:
    """Every role of a declaration, and of its options, is one of :data:`MAP_ROLES` /
    :data:`OPTION_ROLES` (a misspelt role would leave a map out of a study)."""
    for spec in specs:
        unknown = [r for r in getattr(spec, "roles", ()) if r not in MAP_ROLES]
        unknown += [f"{o.name}: {r}" for o in spec.options for r in o.roles if r not in OPTION_ROLES]
        if unknown:
            raise ValueError(f"map {spec.name}: unknown role(s) {unknown}")


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
    _check_roles(specs)
    _unique(specs + list(all_maps()) + [ground_truth()], "map")
    return _ordered(specs)


@cache
def ground_truth():
    """The exact map's declaration (the one module attribute ``GROUND_TRUTH``)."""
    (spec,) = [m.GROUND_TRUTH for m in _modules() if hasattr(m, "GROUND_TRUTH")]
    return spec


@cache
def all_maps():
    """Every declared map (``MAPS``, ``declare_maps()``), in report order (section, then name)."""
    declared = _declared("MAPS")
    _check_layout(declared, "map")
    specs = [s for _, s in declared]
    _check_roles(specs)
    _unique(specs, "map")
    return _ordered(specs)


@cache
def family_pages() -> dict[str, tuple]:
    """{page: every map, half and the ground truth that the modules of page ``docs/<page>.md``
    declare, in report order}: a module's page is its attribute ``PAGE``, else its name."""
    modules = {_short(m): m for m in _modules()}
    declared = _declared("MAPS") + _declared("HALVES")
    declared += [(_short(m), m.GROUND_TRUTH) for m in _modules() if hasattr(m, "GROUND_TRUTH")]
    pages: dict[str, list] = {}
    for module, spec in declared:
        pages.setdefault(getattr(modules[module], "PAGE", module), []).append(spec)
    return {page: _ordered(specs) for page, specs in sorted(pages.items())}
