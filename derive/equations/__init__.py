"""Registry of the report's equations: each entry says whether the printed form holds, and proves it.

The report is "SLIP: Approximate Stance Map for Nonsymmetric Motions and Variable Stiffness". One
module per report section (:data:`SECTION_MODULES`) transcribes its printed displays and registers,
next to each check, the entry's metadata with :func:`equation` or :func:`definition`; a long
section is a package with a module per subsection (``sec5/``: ``sec5_1`` ... ``sec5_2_bottom``),
whose entries are the section's, in the order the package imports them.

Status per entry:

- ``verified``: the printed equation (read through evident OCR noise, named in ``note``) equals
  what :mod:`slipmaps.derive` derives; the check proves it symbolically.
- ``corrected``: the printed form is wrong (a sign, a symbol, a branch); ``note`` says how, the
  check proves the printed form differs from the derivation and the corrected form equals it.
- ``definition``: the equation defines a symbol, states an assumption, an approximation or a
  theorem quoted from elsewhere; nothing to derive.

A check returns nothing and raises :class:`CheckFailed` (through :func:`expect_zero`,
:func:`expect_nonzero` or :func:`expect`) naming the condition that does not hold. :func:`run`
turns a check into an :class:`Outcome`; :func:`main` runs them all (``slipmaps equations``).

Entries are keyed by the report's equation number ("1" ... "151") or, for unnumbered displays, by
their section ("sec2.2.1-polar"). An entry's report subsection (:attr:`Entry.subsection`) is the one
in its key, or for a number the subsection of its section module's ``SUBSECTIONS`` (each
subsection and its first equation number) that the number falls in. An entry may carry ``derived``:
a function returning the SymPy form that the derivation gives (an equation ``sp.Eq`` or a tuple of
them; for a ``corrected`` entry the corrected form), rendered as math on the family pages.
:func:`render_equation_table` gives docs/equations.md.
"""

from __future__ import annotations

import functools
import importlib
import json
import re
import sys
import textwrap
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

__all__ = [
    "STATUSES",
    "SECTION_MODULES",
    "CheckFailed",
    "is_zero",
    "expect_zero",
    "expect_nonzero",
    "expect",
    "Entry",
    "equation",
    "definition",
    "entries",
    "report_entries",
    "forms",
    "by_key",
    "Outcome",
    "run",
    "render_equation_summary",
    "render_equation_table",
    "render_equation_record",
    "to_json",
    "main",
]

STATUSES = ("verified", "corrected", "definition")

#: Section modules (or packages) of this package, in report order. Adding a section is appending its
#: name here.
SECTION_MODULES = ("sec2", "sec3", "sec4", "sec5")

_MESSAGE_CHARS = 160


# --------------------------------------------------------------------------------------------
# Checks: conditions that raise CheckFailed naming what failed.


class CheckFailed(AssertionError):
    """A registry check found that one of its conditions does not hold; the message names it."""


def _short(expr) -> str:
    text = str(expr)
    return text if len(text) <= _MESSAGE_CHARS else text[: _MESSAGE_CHARS - 3] + "..."


def _residual(expr):
    expr = sp.sympify(expr)
    if expr == 0:
        return sp.S.Zero
    return sp.simplify(sp.expand(expr))


def is_zero(expr) -> bool:
    """True when ``expr`` simplifies to exactly zero (``simplify(expand(expr)) == 0``)."""
    return _residual(expr) == 0


def expect_zero(expr, what: str) -> None:
    """Require ``expr`` (a difference) to simplify to zero; ``what`` states the expected equality."""
    residual = _residual(expr)
    if residual != 0:
        raise CheckFailed(f"{what}: difference simplifies to {_short(residual)}")


def expect_nonzero(expr, what: str) -> None:
    """Require ``expr`` (a difference) not to simplify to zero; ``what`` states the expected inequality."""
    if _residual(expr) == 0:
        raise CheckFailed(f"{what}: difference simplifies to 0")


def expect(cond, what: str) -> None:
    """Require ``cond`` to be true: a Python bool or a SymPy ``true``; anything undecided fails."""
    if isinstance(cond, bool | sp.logic.boolalg.BooleanAtom):
        if not bool(cond):
            raise CheckFailed(f"{what}: condition is false")
        return
    raise CheckFailed(f"{what}: condition is undecided ({_short(cond)})")


# --------------------------------------------------------------------------------------------
# Entries and their registration.


@dataclass(frozen=True)
class Entry:
    """One report equation (or unnumbered display) and how the printed form relates to the derivation."""

    key: str
    title: str
    status: str
    note: str
    check: Callable[[], None] | None  # None only for definitions
    section: str  # the section module that registers it, e.g. "sec3"
    #: The derived form (``sp.Eq`` or a tuple of them), computed on demand; None if the entry has text only.
    derived: Callable[[], object] | None = None
    #: Not in the report: an equation slipmaps adds to the model (the leg damping's), checked like the
    #: report's but not counted among them (:func:`report_entries`).
    extension: bool = False

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"equation {self.key}: unknown status {self.status!r}")
        if self.status != "definition" and self.check is None:
            raise ValueError(f"equation {self.key}: a {self.status} entry needs a check")

    @property
    def subsection(self) -> str:
        """The report subsection the entry belongs to: "3.1" for "sec3.1-taylor" and for "11"."""
        if self.key.startswith("sec"):
            return re.match(r"sec([\d.]*\d)", self.key).group(1)
        number = int(self.key)
        module = importlib.import_module(f"{__name__}.{self.section}")
        starts = [name for name, first in getattr(module, "SUBSECTIONS", ()) if first <= number]
        if not starts:
            raise ValueError(f"equation {self.key}: before every subsection of {self.section}.SUBSECTIONS")
        return starts[-1]


_REGISTRY: dict[str, list[Entry]] = {}


def _section_name(module: str) -> str:
    """The section module that ``module`` belongs to: itself (``...equations.sec3``), or the
    section package it lies in (``...equations.sec5.sec5_2_1`` is in ``sec5``)."""
    inside = module.partition(f"{__name__}.")[2]
    return inside.split(".")[0] if inside else module.rsplit(".", 1)[-1]


def _register(entry: Entry, before: str | None = None) -> None:
    for registered in _REGISTRY.values():
        if any(e.key == entry.key for e in registered):
            raise ValueError(f"equation {entry.key}: registered twice")
    section = _REGISTRY.setdefault(entry.section, [])
    if before is None:
        section.append(entry)
    else:
        section.insert(next(i for i, e in enumerate(section) if e.key == before), entry)


def equation(
    key: str,
    title: str,
    status: str,
    note: str = "",
    derived: Callable[[], object] | None = None,
    extension: bool = False,
):
    """Decorator registering the decorated check as the check of equation ``key``.

    Stackable: one function may check several equations, each decorator giving its own title and
    note; stacked decorators register top to bottom, so write them in report order. ``derived``,
    ``extension``: see :class:`Entry`.
    """

    def decorate(check: Callable[[], None]) -> Callable[[], None]:
        entry = Entry(key, title, status, note, check, _section_name(check.__module__), derived, extension)
        below = getattr(check, "_equation_keys", ())  # registered by the decorators under this one
        _register(entry, before=below[0] if below else None)
        check._equation_keys = (key, *below)
        return check

    return decorate


def definition(key: str, title: str, note: str = "", derived: Callable[[], object] | None = None) -> Entry:
    """Register equation ``key`` as a definition (no check), in the calling section module."""
    section = _section_name(sys._getframe(1).f_globals["__name__"])
    entry = Entry(key, title, "definition", note, None, section, derived)
    _register(entry)
    return entry


def forms(*pairs) -> tuple[sp.Eq, ...]:
    """The equations ``lhs = rhs`` of ``(lhs, rhs)`` pairs, unevaluated: what ``derived`` returns."""
    return tuple(sp.Eq(lhs, rhs, evaluate=False) for lhs, rhs in pairs)


def entries() -> list[Entry]:
    """All registry entries in report order: the section modules in :data:`SECTION_MODULES` order."""
    for name in SECTION_MODULES:
        importlib.import_module(f"{__name__}.{name}")
    return [e for name in SECTION_MODULES for e in _REGISTRY.get(name, ())]


def by_key() -> dict[str, Entry]:
    return {e.key: e for e in entries()}


# --------------------------------------------------------------------------------------------
# Running the checks.


@dataclass
class Outcome:
    """Result of :func:`run`: the entry's status when its check passes, else ``"failed"`` and why."""

    entry: Entry
    status: str
    message: str | None = None

    @property
    def failed(self) -> bool:
        return self.status == "failed"


def run(entry: Entry) -> Outcome:
    """Run ``entry``'s check (if any) and report its status or the failed condition.

    Checks are deterministic SymPy computations: a check shared by several entries (one function
    registered for eqs 4 and 5) runs once per process.
    """
    return _run_check(entry.check, entry)


@functools.cache
def _outcome_of(check) -> str | None:
    """None if ``check`` passes, else the failed condition."""
    try:
        result = check()
    except CheckFailed as exc:
        return str(exc)
    except Exception as exc:  # a broken check is a failed check, reported by type
        return f"{type(exc).__name__}: {exc}"
    if result is not None:
        return f"check returned {result!r}: checks signal failure by raising"
    return None


def _run_check(check, entry: Entry) -> Outcome:
    if check is None:
        return Outcome(entry, entry.status)
    message = _outcome_of(check)
    return Outcome(entry, entry.status) if message is None else Outcome(entry, "failed", message)


def render_equation_table() -> str:
    """Markdown table of every entry (docs/equations.md)."""
    lines = [
        "<!-- GENERATED by `slipmaps generate` from derive/equations/ -- do not edit. -->",
        "# Status of the report's equations",
        "",
        "Each entry is checked symbolically by `tests/test_registry.py` (`pytest -k registry`).",
        "`verified`: the printed equation equals the SymPy derivation (read through the OCR noise named",
        "in the note); `corrected`: the printed form is wrong, the note gives the corrected form that the",
        "derivation proves; `definition`: defines a symbol or an assumption.",
        "",
        "| eq | what | status | note |",
        "| --- | --- | --- | --- |",
    ]
    for e in entries():
        note = e.note.replace("|", "\\|").replace("\n", " ")
        lines.append(f"| {e.key} | {e.title} | {e.status} | {note} |")
    extensions = len(entries()) - len(report_entries())
    lines += [
        "",
        f"Totals: {_totals()}"
        + (f"; and {extensions} not in the report (slipmaps' extensions)." if extensions else "."),
    ]
    return "\n".join(lines) + "\n"


def report_entries() -> list[Entry]:
    """The entries of the report's own equations (:func:`entries` without the extensions)."""
    return [e for e in entries() if not e.extension]


def _totals() -> str:
    """The report's entries counted by status: ``120 verified, 25 corrected, 15 definition``."""
    counts = dict.fromkeys(STATUSES, 0)
    for e in report_entries():
        counts[e.status] += 1
    return ", ".join(f"{counts[s]} {s}" for s in STATUSES)


def render_equation_summary() -> str:
    """The README's one line on the registry (the table itself is docs/equations.md)."""
    line = (
        f"Every equation of the report is checked symbolically against the SymPy derivation: {_totals()}; "
        "the table with the corrected forms and their proofs' notes: [docs/equations.md](docs/equations.md)."
    )
    return textwrap.fill(line, 100, break_long_words=False, break_on_hyphens=False) + "\n"


def _proof(check: Callable[[], None]) -> str:
    """Where a check lives: ``derive.equations.sec3.check_eq3`` (the installed package's name off)."""
    return f"{check.__module__.partition('.')[2]}.{check.__name__}"


def render_equation_record() -> str:
    """docs/equations.json: every entry's number, title, status, note, section and its check (the
    proof: ``derive.equations.MODULE.FUNCTION``), in report order; what the report's sections 6-8
    read (runtime/report/), so the runtime needs no SymPy for them. Written by ``slipmaps
    generate`` beside docs/equations.md."""
    rows = [
        {
            "key": e.key,
            "title": e.title,
            "status": e.status,
            "note": e.note,
            "section": e.section,
            "proof": None if e.check is None else _proof(e.check),
            **({"extension": True} if e.extension else {}),
        }
        for e in entries()
    ]
    return json.dumps({"equations": rows}, indent=1) + "\n"


def to_json(outcomes: list[Outcome]) -> list[dict]:
    """One JSON-ready dict per outcome; ``message`` is set for failures only (else None)."""
    return [
        {
            "number": o.entry.key,
            "title": o.entry.title,
            "section": o.entry.section,
            "status": o.status,
            "registered_status": o.entry.status,
            "note": o.entry.note,
            "message": o.message,
        }
        for o in outcomes
    ]


def _format_outcome(o: Outcome) -> str:
    e = o.entry
    mark = "-" if e.check is None else ("FAILED" if o.failed else "ok")
    line = f"{e.key:>20}  {e.status:<10}  {mark:<6}  {e.title}"
    return f"{line}\n{'':>22}{o.message}" if o.failed else line


def main(json_output: bool = False) -> int:
    """Run every check; print the status table (or the JSON list); 1 if any check failed, else 0."""
    outcomes = [run(e) for e in entries()]
    failed = sum(o.failed for o in outcomes)
    if json_output:
        print(json.dumps(to_json(outcomes), indent=2))
    else:
        for o in outcomes:
            print(_format_outcome(o))
        print(f"{failed} check(s) failed" if failed else "all checks pass")
    return 1 if failed else 0
