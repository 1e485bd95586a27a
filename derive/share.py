"""Shared bodies: the kernels of a module that differ only in the kernels they call (and in a few
float constants and their comments) become thin entry points of one body that takes those callees
(and constants) as arguments.

A specialized option (:mod:`.specialize`) gives each of its choices kernels of their own, so that a
first call compiles only the callees of the choice it runs. Many of those kernels are the same code
but for their callees' names: the iterative maps' apex-return kernels differ only in the stance
kernel of their zeroth iterate; the members of a family of maps (the gravity corrections' types 0-4,
``MapSpec.family``) only in the kernel of their rule. :func:`share_bodies` finds them among a
module's lowered kernels (:func:`.lower.lower`): it renders the body once, as ``<common prefix>_<common
suffix>_shared`` (``iterative_stance_zeroth_shared``, ``gravity_stance_shared``) with the differing
callees as trailing arguments (then the differing constants, ``constant<i>``), and makes each
kernel an entry point that returns the shared body's result for its own callees and constants.
The shared body is inlined at numba's IR level into each entry point (``inline="always"``), where
its callee and constant arguments are the entry point's constants: each entry point
compiles to the code its kernel compiled to before, on its choice's first call, and is cached as any
kernel is. (Not inlined, a compiled function taking a function argument is passed the dispatcher's
address, and numba does not cache code that holds an address: measured, "uses dynamic globals".) A
callee argument that is itself ``inline="always"`` is inlined into the entry point as well (numba
resolves the argument to the entry point's global before it inlines).

The kernels keep their names, signatures, layouts, docstrings and batch forms: the index, the
runtime and the tests call them as before. A shared body is not a kernel of the index (no batch
form, no declaration): its name ends with ``_shared`` (:data:`SUFFIX`).
"""

from __future__ import annotations

import copy
import json
import keyword
import os
import re

__all__ = ["SUFFIX", "share_bodies"]

_WORD = re.compile(r"[A-Za-z_]\w*")
#: A float literal of the generated code (``0.0``, ``1.5e-12``), not part of a name or a number.
_FLOAT = re.compile(r"(?<![\w.])\d+\.\d+(?:e[+-]?\d+)?(?![\w.])")

#: The most constants in which the kernels of one shared body may differ (each an argument).
MAX_CONSTANTS = 4

#: The fields of a lowered code node that are prose (a comment's text, a guard's note), not code.
_PROSE = ("text", "doc")

#: The name suffix of every shared body (tests tell them from the declared kernels by it).
SUFFIX = "_shared"

#: A lowered kernel's fields that describe it without shaping its code (docstring, statistics).
_DOC_FIELDS = frozenset(
    {"name", "summary", "equations", "notes", "args", "doc_args", "returns", "ops", "callees", "called"}
)
#: The fields whose strings are code (the callees' names are replaced there in a shared body).
_CODE_FIELDS = ("params", "prologue", "input_guard", "body", "store", "finite_chain", "outputs")


def _pattern(names) -> re.Pattern | None:
    names = sorted(names, key=len, reverse=True)
    return re.compile(r"\b(" + "|".join(map(re.escape, names)) + r")\b") if names else None


def _literals(value, fn, seen: list):
    """``value`` (a lowered kernel's code field) with each float literal replaced by ``fn(i, text)``,
    ``i`` its occurrence (in a fixed order: a dict's fields sorted), its text appended to ``seen``."""
    if isinstance(value, str):

        def one(m: re.Match) -> str:
            seen.append(m.group(0))
            return fn(len(seen) - 1, m.group(0))

        return _FLOAT.sub(one, value)
    if isinstance(value, list):
        return [_literals(v, fn, seen) for v in value]
    if isinstance(value, dict):
        return {f: v if f in _PROSE else _literals(v, fn, seen) for f, v in sorted(value.items())}
    return value


def _silent(value):
    """``value`` (a code field) with its prose blanked: kernels that differ only in a comment (one
    naming the callee a family member calls) share a body, whose comments are its first kernel's with
    the words that differ naming the body's arguments (:func:`_prose`)."""
    if isinstance(value, list):
        return [_silent(v) for v in value]
    if isinstance(value, dict):
        return {f: "" if f in _PROSE else _silent(v) for f, v in value.items()}
    return value


def _key(k: dict) -> tuple[str, list[str], list[str]]:
    """The kernel's code with its callees' names replaced by their order of first use and its float
    literals by a mark; that order; the literals, one per occurrence: two kernels of the same key
    differ only in the callees they call and in constants."""
    fields = {f: v for f, v in k.items() if f not in _DOC_FIELDS}
    literals: list[str] = []
    code = _literals({f: _silent(fields[f]) for f in _CODE_FIELDS}, lambda i, t: "\x01", literals)
    text = json.dumps({**fields, **code}, sort_keys=True, default=repr)
    order: list[str] = []

    def number(m: re.Match) -> str:
        if m.group(0) not in order:
            order.append(m.group(0))
        return f"\x00{order.index(m.group(0))}\x00"

    pattern = _pattern(k["called"])
    return (pattern.sub(number, text) if pattern else text), order, literals


def _common_prefix(names) -> str:
    prefix = os.path.commonprefix(list(names))
    return prefix[: prefix.rfind("_")] if "_" in prefix else ""


def _common_suffix(names) -> str:
    suffix = os.path.commonprefix([n[::-1] for n in names])[::-1]
    return suffix[suffix.find("_") + 1 :] if "_" in suffix else ""


def _names(names: list[str]) -> str:
    """``a_b_{c, d}`` for ``a_b_c, a_b_d``: names by their common prefix."""
    prefix = _common_prefix(names)
    if not prefix:
        return ", ".join(names)
    return prefix + "_{" + ", ".join(n[len(prefix) + 1 :] for n in names) + "}"


def _words(value) -> set[str]:
    """The identifiers of a lowered kernel's code (its comments and guard notes left out)."""
    if isinstance(value, str):
        return set(_WORD.findall(value))
    if isinstance(value, list):
        return set().union(*(_words(v) for v in value))
    if isinstance(value, dict):
        return set().union(*(_words(v) for f, v in value.items() if f not in _PROSE))
    return set()


def _argument_names(columns: list[tuple[str, ...]], taken: set[str]) -> list[str]:
    """A readable argument name for each varying callee: its choices' common prefix, then the first
    word of their common suffix (``zeroth``, ``zeroth_jac``), unique and not a name ``taken``."""
    out: list[str] = []
    for i, names in enumerate(columns):
        words = [w for w in (_common_prefix(names), _common_suffix(names).split("_")[0]) if w]
        name = "_".join(words)
        if not name.isidentifier() or keyword.iskeyword(name) or name in taken or name in out:
            name = f"callee{i}"
        out.append(name)
    return out


def _replace(value, pattern: re.Pattern, names: dict[str, str]):
    if isinstance(value, str):
        return pattern.sub(lambda m: names[m.group(0)], value)
    if isinstance(value, list):
        return [_replace(v, pattern, names) for v in value]
    if isinstance(value, dict):
        return {f: _replace(v, pattern, names) for f, v in value.items()}
    return value


def _prose(first, others: list, callees: dict[str, str]):
    """``first``'s code fields with each word of its prose (a comment) that another member's prose
    has otherwise (the callee a family member calls, named in a comment) replaced by the argument
    that passes that callee: the shared body's comments name what every member runs. ``callees``:
    the first member's callees by argument name; a word names the callee it is, or whose name it
    starts (a comment names a value kernel, the body calls its Jacobian)."""
    if isinstance(first, list):
        return [_prose(v, [o[i] for o in others], callees) for i, v in enumerate(first)]
    if not isinstance(first, dict):
        return first
    out = {}
    for f, v in first.items():
        if f in _PROSE and isinstance(v, str) and any(o.get(f) != v for o in others):
            words = re.split(r"(\W+)", v)
            theirs = [re.split(r"(\W+)", o[f]) for o in others]
            if all(len(t) == len(words) for t in theirs):
                for i, w in enumerate(words):
                    if any(t[i] != w for t in theirs):
                        arg = next((a for c, a in callees.items() if c == w or c.startswith(w + "_")), None)
                        words[i] = arg or w
            out[f] = "".join(words)
        else:
            out[f] = _prose(v, [o.get(f) for o in others], callees) if f not in _PROSE else v
    return out


def share_bodies(kernels: list[dict]) -> list[dict]:
    """``kernels`` (one module's, lowered) with every group of two or more that differ only in their
    callees and in at most :data:`MAX_CONSTANTS` float constants (the iterative maps' ``held`` zeroth
    iterate passes a flag the other choices pass as 0) rendered as one shared body and an entry
    point per kernel. A callee numba inlines (``inline="always"``: the iterative maps' zeroth
    iterates) is inlined through the argument too.
    Deterministic: groups, names and arguments follow the kernels' order."""
    taken = {k["name"] for k in kernels}
    for k in kernels:
        taken |= set(k["called"])
    groups: dict[str, list[tuple[dict, list[str]]]] = {}
    for k in kernels:
        if k["inline"] or k["inline_rows"]:
            continue
        key, order, literals = _key(k)
        groups.setdefault(key, []).append((k, order, literals))
    bodies: dict[str, dict] = {}
    entries: dict[str, dict] = {}
    for members in groups.values():
        if len(members) < 2:
            continue
        columns = list(zip(*(order for _, order, _ in members), strict=True))
        values = list(zip(*(literals for _, _, literals in members), strict=True))
        callees = [i for i, column in enumerate(columns) if len(set(column)) > 1]
        constants = [i for i, column in enumerate(values) if len(set(column)) > 1]
        if not (callees or constants) or len(constants) > MAX_CONSTANTS:
            continue
        first = members[0][0]
        names = [k["name"] for k, _, _ in members]
        # the common prefix, and the common suffix where the names differ in the middle (a family's
        # members: gravity_type<k>_stance -> gravity_stance_shared)
        base = (
            "_".join(part for part in (_common_prefix(names), _common_suffix(names)) if part) or first["name"]
        )
        name = base + SUFFIX
        while name in taken:
            name += "_"
        taken.add(name)
        words = taken | _words({f: first[f] for f in _CODE_FIELDS})
        arguments = _argument_names([columns[i] for i in callees], words)
        arguments += [f"constant{j}" for j in range(len(constants))]
        own = dict(zip((columns[i][0] for i in callees), arguments[: len(callees)], strict=True))
        named = dict(zip(constants, arguments[len(callees) :], strict=True))
        code = {f: first[f] for f in _CODE_FIELDS}
        if own:
            code = _prose(code, [{f: k[f] for f in _CODE_FIELDS} for k, _, _ in members[1:]], own)
            code = _replace(code, _pattern(own), own)
        code = _literals(code, lambda i, t, named=named: named.get(i, t), [])
        body = copy.deepcopy(first)
        body.update(code)
        body.update(
            name=name,
            params=body["params"] + ", " + ", ".join(arguments),
            callees=[c for c in first["callees"] if c[1] not in own],
            shared_by=[k["name"] for k, _, _ in members],
            shared_names=_names([k["name"] for k, _, _ in members]),
            shared_args=arguments,
            shared_what=" and ".join(
                part
                for part in (
                    ("the kernel it calls as " + ", ".join(arguments[: len(callees)])) if callees else "",
                    (
                        ("its constants as " if len(constants) > 1 else "its constant as ")
                        + ", ".join(arguments[len(callees) :])
                    )
                    if constants
                    else "",
                )
                if part
            ),
            ops=first["ops"],
            # inlined at numba's IR level into each entry point: a function argument is a constant
            # there; passed to a compiled function it is an address numba's cache cannot keep
            inline=True,
        )
        bodies[first["name"]] = body
        for k, order, literals in members:
            passed = [order[i] for i in callees] + [literals[i] for i in constants]
            entry = dict(k)
            entry.update(
                body=[{"kind": "return", "code": f"{name}({k['params']}, {', '.join(passed)})"}],
                prologue=[],
                input_guard=None,
                arrays=[],
                rows=0,
                tail=True,
                ops=0,
                callees=[c for c in k["callees"] if c[1] in passed[: len(callees)]],
                entry_of=name,
                passes=passed,
            )
            entries[k["name"]] = entry
    out: list[dict] = []
    for k in kernels:
        if k["name"] in bodies:
            out.append(bodies[k["name"]])
        out.append(entries.get(k["name"], k))
    return out
