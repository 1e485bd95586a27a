"""Line breaking of rendered Python source: no generated line longer than :data:`LIMIT` characters.

The templates write one statement per line, however long (a kernel's expressions run to thousands
of characters); :func:`wrap` breaks every longer line without changing what the code means:

- a statement: inside its brackets, between two tokens (Python joins the lines of an open
  bracket), preferably before a binary operator or after a comma, the continuation indented one
  level more (two for a line opening a block); the right-hand side of an assignment or a
  ``return`` that is not bracketed is put in parentheses first, as are the names of a
  ``from ... import``;
- a comment: into several comment lines;
- a line of a docstring: at spaces, a continuation of an ``name: text`` entry indented under it.

The tokens and their order are unchanged (the statements' syntax trees are the same), so the
compiled code is too; ``tests/test_codegen.py`` checks the limit on every generated file.
"""

from __future__ import annotations

import ast
import io
import itertools
import re
import textwrap
import tokenize

#: The project's line length (pyproject.toml, ruff): no generated line is longer.
LIMIT = 110

#: Operators a line breaks before by preference (a sum's terms, a condition's clauses).
_BINARY = {"+", "-", "&", "|", "and", "or", "if", "else", "==", "!=", "<", "<=", ">", ">="}
_OPEN, _CLOSE = "([{", ")]}"


def wrap(text: str, limit: int = LIMIT) -> str:
    """``text`` (a whole generated module) with every line of more than ``limit`` characters broken."""
    out: list[str] = []
    in_doc = False
    for line in text.split("\n"):
        stripped = line.strip()
        doc_line = in_doc or stripped.startswith('"""')
        if doc_line:
            quotes = stripped.count('"""')
            closes = (in_doc and quotes >= 1) or (not in_doc and quotes >= 2)
            in_doc = not closes
        if len(line) <= limit:
            out.append(line)
        elif doc_line:
            out.extend(_wrap_text(line, limit))
        elif stripped.startswith("#"):
            out.extend(_wrap_comment(line, limit))
        else:
            out.extend(_wrap_code(line, limit))
    return "\n".join(out)


def _wrap_text(line: str, limit: int) -> list[str]:
    indent = line[: len(line) - len(line.lstrip())]
    body = line.strip()
    entry = re.match(r"[\w<>]+: ", body)
    later = indent + ("    " if entry else "")
    return textwrap.wrap(
        body,
        width=limit,
        initial_indent=indent,
        subsequent_indent=later,
        break_long_words=False,
        break_on_hyphens=False,
    ) or [line]


def _wrap_comment(line: str, limit: int) -> list[str]:
    indent = line[: len(line) - len(line.lstrip())] + "# "
    body = line.strip()[1:].strip()
    return textwrap.wrap(
        body, width=limit, initial_indent=indent, subsequent_indent=indent, break_long_words=False
    ) or [line]


def _tokens(code: str) -> list[tokenize.TokenInfo]:
    toks = list(tokenize.generate_tokens(io.StringIO(code + "\n").readline))
    return [t for t in toks if t.type not in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER)]


def _bracketed(code: str) -> str:
    """The statement with its unbracketed long part in parentheses: an assignment's right-hand
    side, a ``return`` value, a ``from ... import``'s names (the rest is already bracketed)."""
    indent = code[: len(code) - len(code.lstrip())]
    body = code.strip()
    m = re.match(r"from (\S+) import (?!\()(.*)$", body)
    if m:
        return f"{indent}from {m.group(1)} import ({m.group(2)})"
    toks = _tokens(body)
    depth = 0
    for i, t in enumerate(toks):
        if t.string in _OPEN:
            depth += 1
        elif t.string in _CLOSE:
            depth -= 1
        elif depth == 0 and t.type == tokenize.OP and t.string == "=" and i > 0:
            rhs = body[t.end[1] :].strip()
            if not _enclosed(rhs) and len(toks) - i > 2:
                return f"{indent}{body[: t.end[1]]} ({rhs})"
            return code
    if body.startswith("return ") and not _enclosed(body[7:].strip()) and len(toks) > 2:
        return f"{indent}return ({body[7:].strip()})"
    return code


def _enclosed(expr: str) -> bool:
    """Whether ``expr`` is one bracketed group, ``( ... )``."""
    if not expr or expr[0] not in _OPEN:
        return False
    depth = 0
    for i, ch in enumerate(expr):
        if ch in _OPEN:
            depth += 1
        elif ch in _CLOSE:
            depth -= 1
            if depth == 0:
                return i == len(expr) - 1
    return False


def _wrap_code(line: str, limit: int) -> list[str]:
    code = _bracketed(line)
    indent = code[: len(code) - len(code.lstrip())]
    more = indent + ("        " if code.rstrip().endswith(":") else "    ")
    # pieces: [whitespace before the token, the token, the quality of a break before it: 2 after a
    # comma or before a binary operator, 1 anywhere else inside brackets, 0 outside them]
    pieces: list[list] = []
    depth, prev_end, prev = 0, 0, None
    for t in _tokens(code):
        if t.type in (tokenize.INDENT, tokenize.DEDENT):
            continue
        quality = 0
        if depth > 0 and prev is not None and prev.string not in _OPEN:
            quality = 1
            if prev.string == "," or (t.string in _BINARY and prev.string not in _BINARY | {","}):
                quality = 2
        pieces.append([code[prev_end : t.start[1]], t.string, quality])
        if t.string in _OPEN:
            depth += 1
        elif t.string in _CLOSE:
            depth -= 1
        prev_end, prev = t.end[1], t
    lines: list[str] = []
    current: list[list] = []

    def width(ps) -> int:
        return sum(len(g) + len(s) for g, s, _ in ps)

    for piece in pieces:
        current.append(piece)
        while width(current) > limit:
            fits = [i for i in range(1, len(current)) if current[i][2] and width(current[:i]) <= limit]
            if not fits:
                break
            good = [i for i in fits if current[i][2] == 2 and width(current[:i]) >= limit // 2]
            k = (good or fits)[-1]
            lines.append("".join(g + s for g, s, _ in current[:k]).rstrip())
            current = [[more, current[k][1], current[k][2]]] + current[k + 1 :]
    lines.append("".join(g + s for g, s, _ in current).rstrip())
    return lines


__all__ = ["LIMIT", "wrap"]


def dense(value, indent: int = 4, limit: int = LIMIT, first: int = 0) -> str:
    """``repr(value)`` of plain data (the generated index) packed into lines of at most ``limit``
    characters: breaks after a comma, a colon or an opening bracket (Python joins the lines of an open
    bracket), a long string into adjacent literals; continuations indented by ``indent``. Linear
    in the length (:func:`wrap` re-reads a statement per break, too slow for a table of 50,000
    characters). ``first``: the characters before the value on its first line."""
    text = repr(value)
    width = limit - max(indent, first) - 2
    pieces, start = [], 0
    for tok in tokenize.generate_tokens(io.StringIO(text).readline):
        if tok.type == tokenize.STRING and len(tok.string) > width:
            pieces.append(text[start : tok.start[1]].strip())
            words = []
            for w in re.split(r"(?<= )", ast.literal_eval(tok.string)):
                words += [w] if len(repr(w)) <= width else list(w)
            chunk = ""
            for w in words:
                if chunk and len(repr(chunk + w)) > width:
                    pieces.append(repr(chunk))
                    chunk = ""
                chunk += w
            pieces.append(repr(chunk))
            start = tok.end[1]
        elif tok.type == tokenize.OP and (tok.string in ",:" or tok.string in _OPEN):
            end = tok.end[1]
            if pieces and start == tok.start[1] and tok.string in ",:":
                pieces[-1] += tok.string
            else:
                pieces.append(text[start:end].strip())
            start = end
    pieces.append(text[start:].strip())
    lines, line = [], ""
    for piece in filter(None, pieces):
        joined = f"{line} {piece}" if line and not line.endswith(tuple(_OPEN)) else line + piece
        if line and len(joined) + (indent if lines else first) > limit:
            lines.append(line)
            line = piece
        else:
            line = joined
    lines.append(line)
    out = ("\n" + " " * indent).join(lines)
    refs = _refs(value)
    text = out.replace("\n", " ")
    back = eval(text, {"__builtins__": {}}, refs) if refs else ast.literal_eval(text)  # noqa: S307
    if back != _resolved(value):
        raise AssertionError("dense(): the packed text does not read back as the value")
    return out


class Ref:
    """A reference, in data :func:`dense` packs, to a constant of the module defined before it:
    rendered as its bare ``name`` (:func:`intern_repeats`)."""

    def __init__(self, name: str, value):
        self.name, self.value = name, value

    def __repr__(self) -> str:
        return self.name


def _children(value):
    if isinstance(value, dict):
        return value.values()
    return value if isinstance(value, list) else ()


def _refs(value) -> dict:
    """The constants ``value`` references, by name, with their values resolved."""
    if isinstance(value, Ref):
        return {value.name: _resolved(value.value)}
    out: dict = {}
    for child in _children(value):
        out.update(_refs(child))
    return out


def _resolved(value):
    """``value`` with every :class:`Ref` replaced by the value it names."""
    if isinstance(value, Ref):
        return _resolved(value.value)
    if isinstance(value, dict):
        return {k: _resolved(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_resolved(v) for v in value]
    return value


def intern_repeats(tables: dict, prefix: str = "_repeated", least: int = 120) -> list[tuple[str, object]]:
    """``tables`` (name -> plain data) as a list of module constants in which every list or dict
    that occurs more than once and takes at least ``least`` characters is written once, as a
    constant ``<prefix><i>`` defined before its first use, and referenced (:class:`Ref`) elsewhere:
    the index's repeated layouts and options, published once. Deterministic: constants
    are numbered in the order of first use, a table's fields in their order."""
    counts: dict[str, int] = {}

    def count(value):
        if isinstance(value, (list, dict)):
            counts[repr(value)] = counts.get(repr(value), 0) + 1
            for child in _children(value):
                count(child)

    for value in tables.values():
        count(value)
    shared = {r for r, c in counts.items() if c > 1 and len(r) >= least}
    names: dict[str, Ref] = {}
    out: list[tuple[str, object]] = []
    number = itertools.count()

    def rebuild(value):
        """``value`` with its children replaced."""
        if isinstance(value, dict):
            return {k: replace(v) for k, v in value.items()}
        return [replace(v) for v in value]

    def replace(value):
        if not isinstance(value, (list, dict)):
            return value
        key = repr(value)
        if key not in names and key in shared:
            new = rebuild(value)  # its repeated parts first, numbered before it
            names[key] = Ref(f"{prefix}{next(number)}", new)
            out.append((names[key].name, new))
        return names[key] if key in names else rebuild(value)

    for name, value in tables.items():
        key = repr(value)
        if isinstance(value, (list, dict)) and key in shared and key not in names:
            # a table the others repeat: they reference the table itself
            names[key] = ref = Ref(name, None)
            ref.value = rebuild(value)
            out.append((name, ref.value))
        else:
            out.append((name, replace(value)))
    return out
