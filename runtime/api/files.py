"""The files the commands read and the records they write: :func:`read_toml` (a sweep definition,
a control scenario) and :func:`rounded` (a JSON record's numbers to 6 significant digits, NaN as
``null``; docs/*.json of the studies and of the control evaluation)."""

from __future__ import annotations

import math
from pathlib import Path

__all__ = ["read_toml", "rounded"]


def read_toml(path: str | Path) -> dict:
    """A TOML file as a dict (tomllib, Python 3.11+; tomli on 3.10); ValueError naming the file."""
    try:
        import tomllib
    except ImportError:  # Python 3.10
        try:
            import tomli as tomllib
        except ImportError:
            raise ValueError("reading a TOML file needs Python 3.11 (tomllib) or the tomli package") from None
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except OSError as exc:
        raise ValueError(f"cannot read {path}: {exc.strerror}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not valid TOML: {exc}") from None
    except UnicodeDecodeError as exc:  # a binary file: TOML is UTF-8 text
        raise ValueError(f"{path}: not a TOML file: not UTF-8 text (byte {exc.start})") from None


def rounded(x, digits: int = 6):
    """``x`` (a float, or dicts / lists of them) to ``digits`` significant digits; non-finite -> None."""
    if isinstance(x, float):
        return None if not math.isfinite(x) else float(f"{x:.{digits}g}")
    if isinstance(x, dict):
        return {k: rounded(v, digits) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [rounded(v, digits) for v in x]
    return x
