"""Number formatting shared by the generated reports (docs/accuracy.md, docs/stiffness.md).

The JSON records keep 6 significant digits (:func:`rounded`); the markdown shows 3 (:func:`sig`,
:func:`pct`). Non-finite numbers are ``null`` in JSON and ``n/a`` in markdown.
"""

from __future__ import annotations

import math

__all__ = ["rounded", "sig", "pct", "fails"]


def rounded(x, digits: int = 6):
    """``x`` (a float, or dicts / lists of them) to ``digits`` significant digits; non-finite -> None."""
    if isinstance(x, float):
        return None if not math.isfinite(x) else float(f"{x:.{digits}g}")
    if isinstance(x, dict):
        return {k: rounded(v, digits) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [rounded(v, digits) for v in x]
    return x


def sig(x: float, digits: int = 3) -> str:
    """``x`` to ``digits`` significant digits, fixed-point between 1e-3 and 1e4."""
    if x is None or not math.isfinite(x):
        return "n/a"
    if x == 0.0:
        return "0"
    if 1e-3 <= abs(x) < 1e4:
        decimals = max(digits - 1 - math.floor(math.log10(abs(x))), 0)
        s = f"{x:.{decimals}f}"
        return f"{float(s):.{max(digits - 1 - math.floor(math.log10(abs(float(s)))), 0)}f}"
    return f"{x:.{digits - 1}e}"


def pct(x: float) -> str:
    """A fraction as a percentage, 3 significant digits."""
    return "n/a" if x is None or not math.isfinite(x) else f"{sig(100.0 * x)} %"


def fails(d: dict[str, int]) -> str:
    """Failure counts by status: ``2 `FALL`, 1 `NO_LIFTOFF` `` (``0`` when none)."""
    return ", ".join(f"{n} `{k}`" for k, n in d.items()) or "0"
