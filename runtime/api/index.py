"""The maps the runtime knows, and option resolution: read from the generated index.

Everything here is read from ``slipmaps.generated.maps_index`` (written by ``slipmaps generate``
from the declarations in ``derive/maps/``); nothing restates a map, a parameter list, a kernel's
arguments or an output layout. Each map's row gives, for every role it has (``stance``,
``state_at``, ``apex_return``, ``stance_jacobian``, ``apex_return_jacobian``; ``half`` for a
half-stance map), the kernel's calling convention: its module and name, its arguments by name,
its batch form's row arguments and argument order, and its outputs (:class:`KernelSpec`). The
runtime fills those arguments by name (:mod:`.calls`). ``"exact"`` (the numerical ground truth,
DOP853) is declared and generated like the other maps; its option ``method="scipy"`` runs the
``solve_ivp`` reference instead (an option choice with a backend of its own).
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from functools import cache, cached_property

from slipmaps.generated import maps_index

from .names import public_names
from .numeric import NotANumber, is_real, num
from .params import PARAMETERS, SlipParams
from .validate import check_params

__all__ = [
    "EXACT",
    "HalfInfo",
    "KernelSpec",
    "MapInfo",
    "Option",
    "get",
    "get_half",
    "halves",
    "lookup",
    "maps",
    "model_kernels",
    "names",
    "takers",
]

#: The name of the ground truth, the exact map.
EXACT: str = maps_index.EXACT["name"]


@dataclass(frozen=True)
class KernelSpec:
    """One role kernel's calling convention (the index's ``kernels`` entry of a role):
    ``kernel(x, p, out) -> status`` and its batch form ``kernel_rows(X, p, OUT, STATUS)``, the
    vectors laid out by the names :attr:`x`, :attr:`p` and :attr:`out` (derive/ir.py, ``Layout``)."""

    module: str
    name: str
    x: tuple[str, ...]  # the inputs, in the order of ``x`` (a batch's columns of ``X``)
    p: tuple[str, ...]  # the map's parameter record: parameters and kernel options
    outputs: tuple[str, ...]  # the values written into ``out`` (a Jacobian's derivatives follow)
    wrt: tuple[str, ...] = ()  # a Jacobian's inputs: its columns
    #: With specialized options (a kernel per choice; ``name`` is the default choice's): the generic
    #: name, which the suffix of a choice (the row's ``choices``) completes.
    base: str | None = None

    @classmethod
    def of(cls, row: dict) -> KernelSpec:
        return cls(
            module=row["module"],
            name=row["name"],
            x=tuple(row["x"]),
            p=tuple(row["p"]),
            outputs=tuple(row["out"]),
            wrt=tuple(row.get("wrt", ())),
            base=row.get("base"),
        )

    @cached_property
    def public_outputs(self) -> tuple[str, ...]:
        """The outputs by the API's names (the next apex ``next_apex_height`` ...;
        ``slipmaps.runtime.api.names``)."""
        return public_names(self.outputs)

    @cached_property
    def record_only(self) -> frozenset[str]:
        """Names of the parameter record that are not inputs; a batch's per-row arrays of these
        make a record per row (``layout_rows`` of runtime/api/calls.py)."""
        return frozenset(self.p) - frozenset(self.x)

    @property
    def width(self) -> int:
        """The length of ``out``: the outputs, and for a Jacobian d output / d input for every
        (output, input) pair after them (row-major)."""
        return len(self.outputs) * (1 + len(self.wrt))

    def chosen(self, suffix: str) -> KernelSpec:
        """The kernel of a choice of the specialized options, by its name suffix (itself without)."""
        return self if self.base is None else replace(self, name=self.base + suffix)

    def functions(self):
        """(row kernel, batch form) of the generated module (imported on first use)."""
        module = importlib.import_module(f"slipmaps.generated.{self.module}")
        return getattr(module, self.name), getattr(module, f"{self.name}_rows")


@dataclass(frozen=True)
class Option:
    """One option of a map (see ``docs/maps.md``): a choice, an integer or a float."""

    name: str
    kind: str  # "choice", "int" or "float"
    default: object
    doc: str
    choices: tuple[str, ...] = ()
    low: float | None = None
    high: float | None = None
    at_rest_length: tuple[str, ...] = ()  # choices that need touchdown at l0 (else INVALID_INPUT)
    kernel: bool = True  # a kernel argument (else it selects the implementation or the kernels)
    #: Whether each choice has kernels of its own, the option then not a kernel argument (the call
    #: picks the kernels of its choice).
    specialize: bool = False
    backends: Mapping[str, str] = field(default_factory=dict)  # choice -> module with a BACKEND
    #: Which of its values the studies measure (derive/maps/__init__.py's OPTION_ROLES).
    roles: tuple[str, ...] = ()

    def encode(self, map_name: str, value: object) -> float:
        """The kernel argument for ``value`` (a choice's index); ValueError naming the valid values,
        TypeError for a number option given a string."""
        where = f"map {map_name!r} option {self.name!r}"
        if self.kind == "choice":
            if value not in self.choices:
                raise ValueError(
                    f"{where} must be one of {', '.join(map(repr, self.choices))}, got {value!r}"
                )
            return float(self.choices.index(value))
        if not is_real(value):
            raise NotANumber(f"{where} must be a number, got {type(value).__name__} {value!r}")
        x = float(value)
        if not math.isfinite(x):
            raise ValueError(f"{where} must be finite, got {num(x)}")
        if self.kind == "int" and x != math.floor(x):
            raise ValueError(f"{where} must be a whole number, got {num(x)}")
        if (self.low is not None and x < self.low) or (self.high is not None and x > self.high):
            low = "-inf" if self.low is None else f"{self.low:g}"
            high = "inf" if self.high is None else f"{self.high:g}"
            raise ValueError(f"{where} must lie in [{low}, {high}], got {num(x)}")
        return x

    def as_dict(self) -> dict:
        return {
            "name": self.name,
            "kind": self.kind,
            "default": self.default,
            "doc": self.doc,
            "choices": list(self.choices),
            "low": self.low,
            "high": self.high,
            "at_rest_length": list(self.at_rest_length),
            "kernel": self.kernel,
            "specialize": self.specialize,
            "backends": dict(self.backends),
        }


@dataclass(frozen=True)
class MapInfo:
    """One row of the index: what ``slipmaps maps`` lists."""

    name: str
    title: str
    section: str
    equations: tuple[str, ...]
    requires: tuple[str, ...]
    params: tuple[str, ...]
    options: tuple[Option, ...]
    summary: str = ""
    module: str | None = None
    #: Role -> the kernel's calling convention (:class:`KernelSpec`).
    kernels: Mapping[str, KernelSpec] = field(default_factory=dict)
    extras: tuple[str, ...] = ()
    #: True when the map reproduces the report's printed formulas, errors included (no accuracy claim).
    as_printed: bool = False
    #: Statuses the approximation itself returns on gaits the exact stance completes.
    approximation_statuses: tuple[str, ...] = ()
    #: What the studies and the command line do with the map (derive/maps/__init__.py's MAP_ROLES).
    roles: tuple[str, ...] = ()
    #: The options with kernels per choice, and each choice's kernel name suffix by its key (the
    #: options' values joined by commas).
    specialized: tuple[str, ...] = ()
    choices: Mapping[str, str] = field(default_factory=dict)
    #: The kernel arguments a member of a family of maps fixes (one body for several maps, its rule
    #: an option: the gravity corrections' types 0-4), by name; not options of the map.
    fixed: Mapping[str, float] = field(default_factory=dict)

    @property
    def ground_truth(self) -> bool:
        """True for the exact map, the numerical ground truth every approximation is compared with."""
        return self.name == EXACT

    def has(self, role: str) -> bool:
        """Whether the map has a kernel for ``role`` (``state_at``: a trajectory; ``*_jacobian``)."""
        return role in self.kernels

    @property
    def has_trajectory(self) -> bool:
        """True when :func:`slipmaps.trajectory` can sample the map's stance at any time (a
        state-at-time kernel); False for a map that computes its event states only (touchdown,
        bottom, liftoff: ``iterative``, ``iterative-report``)."""
        return self.has("state_at")

    def option(self, name: str) -> Option:
        for o in self.options:
            if o.name == name:
                return o
        valid = ", ".join(o.name for o in self.options) or "none"
        raise ValueError(f"map {self.name!r} has no option {name!r} (its options: {valid})")

    def resolve(self, options: dict) -> dict[str, object]:
        """User options (validated, unknown names rejected) merged over the defaults."""
        for key in options:
            self.option(key)
        return {o.name: options.get(o.name, o.default) for o in self.options}

    def encode(self, resolved: dict) -> dict[str, float]:
        """The resolved option values (:meth:`resolve`), each checked (ValueError naming the valid
        values), and those that are kernel arguments by name (a choice as its index)."""
        encoded = {o.name: o.encode(self.name, resolved[o.name]) for o in self.options}
        return {**self.fixed, **{o.name: encoded[o.name] for o in self.options if o.kernel}}

    def kernels_for(self, resolved: dict) -> Mapping[str, KernelSpec]:
        """Every role's kernel for the resolved options (:meth:`resolve`): with specialized options
        the kernels of their choice."""
        if not self.specialized:
            return self.kernels
        suffix = self.choices[",".join(str(resolved[o]) for o in self.specialized)]
        return {role: spec.chosen(suffix) for role, spec in self.kernels.items()}

    def backend(self, resolved: dict) -> str | None:
        """The module whose ``BACKEND`` runs the map with these options, None for its generated
        kernels (an option choice with a backend of its own, e.g. ``method="scipy"``)."""
        for o in self.options:
            module = o.backends.get(resolved[o.name])
            if module is not None:
                return module
        return None

    def check_params(self, params: SlipParams) -> None:
        """ValueError when ``params`` break a requirement of the map (a constant stiffness) or give a
        parameter the map does not model (``check_modelled`` below)."""
        check_params(params)
        check_modelled(self, params)
        if "constant_stiffness" in self.requires and not params.constant_stiffness:
            others = [m.name for m in maps() if "constant_stiffness" not in m.requires]
            raise ValueError(
                f"map {self.name!r} needs a constant leg stiffness (k_c == k_d), got k_c={num(params.k_c)}, "
                f"k_d={num(params.k_d)}; maps that accept k_c != k_d: {', '.join(others)}"
            )

    def as_dict(self) -> dict:
        return {
            "name": self.name,
            "title": self.title,
            "section": self.section,
            "equations": [int(e) if e.isdigit() else e for e in self.equations],
            "requires": list(self.requires),
            "params": list(self.params),
            "options": [o.as_dict() for o in self.options],
            "summary": self.summary,
            "extras": list(self.extras),
            "as_printed": self.as_printed,
            "approximation_statuses": list(self.approximation_statuses),
        }


@dataclass(frozen=True)
class HalfInfo(MapInfo):
    """One half-stance map of the index (``HALVES``): from ``start`` ("touchdown" or "bottom") to
    ``end`` ("bottom" or "liftoff"), a half of the whole-stance map ``whole``."""

    whole: str = ""
    start: str = ""
    end: str = ""

    def as_dict(self) -> dict:
        return {**super().as_dict(), "whole": self.whole, "start": self.start, "end": self.end}


def _option(row: dict) -> Option:
    return Option(
        name=row["name"],
        kind=row["kind"],
        default=row["default"],
        doc=row["doc"],
        choices=tuple(c["value"] for c in row["choices"]),
        low=row["low"],
        high=row["high"],
        at_rest_length=tuple(row.get("at_rest_length", ())),
        kernel=row["kernel"],
        specialize=row.get("specialize", False),
        backends=dict(row["backends"]),
        roles=tuple(row.get("roles", ())),
    )


def _info(r: dict, cls: type[MapInfo] = MapInfo, **extra) -> MapInfo:
    """An index row (``MAPS``, ``EXACT`` or ``HALVES``) as ``cls``, with ``extra`` fields."""
    return cls(
        name=r["name"],
        title=r["title"],
        section=r["section"],
        equations=tuple(r["equations"]),
        requires=tuple(r["requires"]),
        params=tuple(r["params"]),
        options=tuple(_option(o) for o in r["options"]),
        summary=r["summary"],
        module=r["module"],
        kernels={role: KernelSpec.of(k) for role, k in r["kernels"].items()},
        extras=tuple(e["name"] for e in r["extras"]),
        as_printed=r.get("as_printed", False),
        approximation_statuses=tuple(r.get("approximation_statuses", ())),
        roles=tuple(r.get("roles", ())),
        specialized=tuple(r.get("specialized", ())),
        choices=dict(r.get("choices", {})),
        fixed=dict(r.get("fixed", {})),
        **extra,
    )


#: The parameters only some maps model (their row's ``unmodelled`` in ``derive/params.py``): name ->
#: the value a map that does not declare it assumes.
UNMODELLED = {r["name"]: r["unmodelled"] for r in PARAMETERS if "unmodelled" in r}
_DOCS = {r["name"]: f"{r['doc'].split(',')[0]} [{r['unit']}]" for r in PARAMETERS}


def takers(parameter: str) -> tuple[str, ...]:
    """The maps and half-stance maps that declare ``parameter`` (their index rows' ``params``)."""
    return tuple(m.name for m in (*maps(), *halves()) if parameter in m.params)


def check_modelled(info: MapInfo, params: SlipParams) -> None:
    """ValueError, one line, when ``params`` give a parameter that ``info`` does not model (not in its
    ``params``) another value than the one it assumes (:data:`UNMODELLED`: the leg damping c = 0),
    naming the map, the parameter and the maps that take it."""
    for name, assumed in UNMODELLED.items():
        value = getattr(params, name)
        if value != assumed and name not in info.params:
            raise ValueError(
                f"map {info.name!r} does not model {name} ({_DOCS[name]}): got {name}={num(value)}, it "
                f"assumes {name}={num(assumed)}; maps that take {name}: {', '.join(takers(name)) or 'none'}"
            )


@cache
def maps() -> tuple[MapInfo, ...]:
    """Every map: the generated ones in report order, then ``"exact"``."""
    return tuple(_info(r) for r in maps_index.MAPS) + (_info(maps_index.EXACT),)


@cache
def halves() -> tuple[HalfInfo, ...]:
    """Every half-stance map, in report order."""
    return tuple(
        _info(r, HalfInfo, whole=r["whole"], start=r["start"], end=r["end"]) for r in maps_index.HALVES
    )


@cache
def model_kernels() -> Mapping[str, KernelSpec]:
    """The model's kernels the runtime calls by name (the index's ``MODEL``: the flights, the
    equations of motion, the energy, the coordinate maps, ...), each a role kernel."""
    return {name: KernelSpec.of(row) for name, row in maps_index.MODEL.items()}


def lookup(name: str) -> MapInfo:
    """The map or half-stance map called ``name`` (:class:`HalfInfo` for a half); ValueError
    listing the valid names of both."""
    for h in halves():
        if h.name == name:
            return h
    return get(name)


def get_half(name: str) -> HalfInfo:
    """The half-stance map called ``name``; ValueError listing the valid names."""
    for h in halves():
        if h.name == name:
            return h
    if name in names():
        raise ValueError(f"{name!r} is a whole-stance map; the half-stance maps are: " + _half_names())
    raise ValueError(f"unknown half-stance map {name!r}; the half-stance maps are: " + _half_names())


def _half_names() -> str:
    return ", ".join(h.name for h in halves())


def names() -> tuple[str, ...]:
    return tuple(m.name for m in maps())


def get(name: str) -> MapInfo:
    """The map called ``name``; ValueError listing the valid names."""
    for m in maps():
        if m.name == name:
            return m
    if any(h.name == name for h in halves()):
        raise ValueError(
            f"{name!r} is a half-stance map (slipmaps.half_stance); the whole-stance maps are: "
            f"{', '.join(names())}"
        )
    raise ValueError(f"unknown map {name!r}; the maps are: {', '.join(names())}")
