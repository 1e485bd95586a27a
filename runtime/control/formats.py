"""Numbers as the control study's pages print them (docs/control.md: :mod:`.report`, :mod:`.report_blind`):
three significant digits, "n/a" for a missing or non-finite value."""

from __future__ import annotations

import math

from .evaluation import D_MIN as EVAL_D_MIN

__all__ = ["f", "largest", "mm", "pct", "share"]


def f(x, digits: int = 3) -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "n/a"
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 1e4:
        return f"{x:.{max(digits - 1 - math.floor(math.log10(abs(x))), 0)}f}"
    return f"{x:.{digits - 1}e}"


def mm(x) -> str:
    return "n/a" if x is None else f(1000.0 * x)


def pct(x) -> str:
    return "n/a" if x is None else f(100.0 * x)


def share(x) -> str:
    return "n/a" if x is None else f"{100.0 * x:.1f} %"


def largest(d) -> str:
    """The largest d without a fall; 0 means a fall even at the smallest d searched."""
    if d is None:
        return "n/a"
    return f"< {f(EVAL_D_MIN)}" if d == 0 else f(d)
