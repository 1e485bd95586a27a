"""Argument helpers every command shares: the SLIP parameter flags, map options, image paths.

The parameter flags come from the parameter table (``derive/params.py``: ``--m``, ``--l0``, ``--k``,
``--k-c``, ``--k-d``, ``--g-s``, ``--g-f``, ``--q-r-td``, ``--q-r-lo``, each with its unit and
default); a new parameter there is a new flag here. A bad value is a ValueError naming the flag as
typed (the command line prints it as one line, exit 2).
"""

from __future__ import annotations

import argparse

from slipmaps.derive import params as _table

from ..api.numeric import num
from ..api.params import HUMAN_RUNNER, ParamError, ParamTypeError, SlipParams
from ..api.paths import writable_file

__all__ = ["IMAGE_FORMATS", "add_params", "image_path", "map_options", "params_of", "stiffness_note"]


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def _dest(name: str) -> str:
    return name


def add_params(p: argparse.ArgumentParser) -> None:
    """The parameter flags (module docstring), all defaulting to the table's value (None: unset)."""
    g = p.add_argument_group("SLIP parameters (SI units; default: the human runner)")
    rows = [(r["name"], r) for r in _table.PARAMETERS]
    rows = rows[:2] + list(_table.ALIASES.items()) + rows[2:]
    sets = {n: alias for alias, a in _table.ALIASES.items() for n in a["sets"]}
    for name, row in rows:
        if name in _table.ALIASES:
            default = f"{HUMAN_RUNNER.as_dict()[row['sets'][0]]:g}"
            extra = f"; sets {' = '.join(row['sets'])}"
        elif name in sets:
            default = f"{row['default']:g}"
            others = [n for n in _table.ALIASES[sets[name]]["sets"] if n != name]
            extra = f"; alone: {', '.join(others)} stays {default}"
        elif isinstance(row["default"], str):
            default, extra = row["default"], ""
        else:
            default, extra = f"{row['default']:g}", ""
        if name == "q_r_td":
            extra += "; --touchdown: Q_R"
        g.add_argument(
            _flag(name),
            dest=_dest(name),
            type=float,
            default=None,
            help=f"{row['doc']} [{row['unit']}] (default {default}{extra})",
        )


def params_of(args: argparse.Namespace) -> SlipParams:
    """The parameters as given (an unset one is the table's default); a bad value is a ValueError
    naming the flag typed (``--k`` when it set both stiffnesses). With ``--touchdown`` the touchdown
    leg length is the state's q_r: a different ``--q-r-td`` is refused."""
    given = {n: getattr(args, _dest(n)) for n in (*(r["name"] for r in _table.PARAMETERS), *_table.ALIASES)}
    for alias, a in _table.ALIASES.items():
        if given[alias] is not None and any(given[n] is not None for n in a["sets"]):
            flags = "/".join(_flag(n) for n in a["sets"])
            raise ValueError(
                f"{_flag(alias)} sets both stiffnesses: give either {_flag(alias)} or {flags}, not both"
            )
    touchdown = getattr(args, "touchdown", None)
    if touchdown is not None and given["q_r_td"] is not None and given["q_r_td"] != touchdown[0]:
        raise ValueError(
            f"--q-r-td {num(given['q_r_td'])} contradicts --touchdown, whose q_r {num(touchdown[0])} is the "
            "touchdown leg length: drop --q-r-td (it is taken from the state)"
        )
    try:
        return SlipParams(**{n: v for n, v in given.items() if v is not None})
    except (ParamError, ParamTypeError) as exc:
        raise ValueError(f"{_flag(exc.field)} {exc.problem}, got {num(exc.value)}") from None


def stiffness_note(args: argparse.Namespace, params: SlipParams) -> str | None:
    """A note when one of --k-c/--k-d alone made k_c != k_d (the other kept its default)."""
    if params.constant_stiffness or (args.k_c is None) == (args.k_d is None):
        return None
    given, other = ("--k-c", "k_d") if args.k_c is not None else ("--k-d", "k_c")
    return (
        f"only {given} given: {other} keeps its default {HUMAN_RUNNER.k_c:g} N/m, so k_c != k_d "
        "(variable stiffness); give both, or --k for a constant stiffness"
    )


#: The image formats --plot and gait --figure can write (matplotlib's; the suffix chooses).
IMAGE_FORMATS = ("png", "pdf", "svg", "jpg", "jpeg", "eps", "ps", "tif", "tiff", "webp")


def image_path(flag: str, path: str, example: str = "compare") -> str:
    """An image path given by ``flag`` (``--plot``, ``--figure``), checked before any work by
    :func:`~.paths.writable_file`: an image suffix, its directory created when missing and
    writable; ValueError (one line naming the flag) otherwise."""
    writable_file(flag, path, IMAGE_FORMATS, described="an image file", example=example)
    return path


#: An option's kind in a message ("must be a whole number"; the index's own words).
_KIND_WORDS = {"int": "a whole number", "float": "a number"}


def map_options(name: str, pairs: list[str] | None) -> dict:
    """``KEY=VALUE`` strings -> options of map ``name``, typed from the index."""
    from ..api.index import lookup

    info = lookup(name)
    out = {}
    for pair in pairs or ():
        key, sep, value = pair.partition("=")
        if not sep:
            raise ValueError(f"--option takes KEY=VALUE, got {pair!r}")
        opt = info.option(key.strip())
        value = value.strip()
        try:
            out[opt.name] = (
                value if opt.kind == "choice" else (int(value) if opt.kind == "int" else float(value))
            )
        except ValueError:
            raise ValueError(
                f"map {name!r} option {opt.name!r} must be {_KIND_WORDS[opt.kind]}, got {value!r}"
            ) from None
    return out


def docs_out(out: str | None, quick: bool):
    """The directory a study writes into: ``--out DIR`` (checked writable), else the checkout's
    docs/; a ``--quick`` study never writes docs/ (it needs ``--out``). ValueError, one line."""
    from ..api.paths import writable_dir
    from ..studies.checkout import docs_dir

    if out is not None:
        return writable_dir("--out", out)
    if quick:
        raise ValueError("--quick writes a reduced study: give --out DIR (never docs/)")
    docs = docs_dir()
    if docs is None:
        raise ValueError("slipmaps does not run from a source checkout, so there is no docs/: give --out DIR")
    return docs
