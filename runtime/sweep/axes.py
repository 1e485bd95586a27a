"""What a sweep can vary (its quantities, with units and domains) and which point is row ``i``.

Quantities (SI units; leg angle from the vertical, counterclockwise positive):

- the inputs of the batch API of the sweep's kind: ``apex_return`` (:func:`slipmaps.apex_return_batch`)
  ``apex_height`` [m], ``apex_speed`` [m/s] (signed), ``touchdown_angle`` [rad], ``ground`` [m]
  (default 0); ``stance``
  (:func:`slipmaps.stance_batch`) the polar touchdown state ``q_r_td`` [m], ``q_rd_td`` [m/s],
  ``q_th_td`` [rad], ``q_thd_td`` [rad/s] (the names of the generated index);
- the parameters: every :class:`~slipmaps.SlipParams` field (``m``, ``l0``, ``k_c``, ``k_d``, ``g_s``,
  ``g_f``, ``q_r_td``, ``q_r_lo``), ``k`` (both stiffnesses) and ``k_d_over_k_c`` (the stiffness ratio
  of report section 5: ``k_d = k_c * k_d_over_k_c``).

An :class:`Axis` is a list of values or a range ``low..high``: on a grid ``num`` points, linearly or
logarithmically spaced; in a random sample uniform (log-uniform) on the range, or uniform over the
listed values.

Rows, computed per chunk from the row index alone (never the whole grid):

- grid: row ``i`` is the C-order (last axis fastest) multi-index of ``i`` over the axes;
- random: row ``i``'s value on axis ``j`` comes from the ``(i * n_axes + j)``-th double of
  ``numpy.random.Philox(key=seed)``, so a row does not depend on the chunk it falls in.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from slipmaps.derive import params as _table

from ..api.validate import CHECKS, leg_angle, positive, real

__all__ = [
    "Quantity",
    "Axis",
    "AXIS_KEYS",
    "KINDS",
    "RATIO",
    "CHUNK_ROWS_GENERATED",
    "CHUNK_ROWS_EXACT",
    "quantities",
    "grid_points",
    "random_points",
]

#: The stiffness-ratio quantity: k_d = k_c * k_d_over_k_c.
RATIO = "k_d_over_k_c"
#: Default rows per chunk (the unit of progress and of resuming): a generated map's chunk takes
#: ~0.03-0.5 s (0.1-2 us a row), the exact map's ~0.3-0.7 s with the compiled simulator (10-20 us
#: a row; method="scipy" is ~2 ms a row: give it a smaller chunk_rows).
CHUNK_ROWS_GENERATED = 1 << 18
CHUNK_ROWS_EXACT = 1 << 15


@dataclass(frozen=True)
class Quantity:
    """A sweepable quantity: ``role`` "input" (a per-row argument of the batch API) or "param"."""

    name: str
    unit: str
    doc: str
    role: str
    check: Callable[[str, object], float]  # ValueError naming the quantity when out of its domain
    optional: bool = False  # an input with a default: ``default``, or the parameter of its name
    default: float | None = None


def _any_real(name: str, value: object) -> float:
    return real(name, value)


#: The apex-return inputs (``derive/params.py``); ``ground`` is optional (0: flat ground).
_APEX_INPUTS = tuple(
    Quantity(r["name"], r["unit"], r["doc"], "input", CHECKS[r["domain"]], "default" in r, r.get("default"))
    for r in _table.APEX_INPUTS
)
_STANCE_INPUTS = (
    Quantity(
        "q_r_td", "m", "touchdown leg length (default: the parameters' q_r_td)", "input", positive, True
    ),
    Quantity("q_rd_td", "m/s", "touchdown leg length rate (negative: compressing)", "input", _any_real),
    Quantity("q_th_td", "rad", "touchdown leg angle, |q_th_td| < pi/2", "input", leg_angle),
    Quantity("q_thd_td", "rad/s", "touchdown leg angle rate", "input", _any_real),
)
#: The inputs of each kind of sweep, in the order of its batch API.
KINDS: dict[str, tuple[Quantity, ...]] = {"apex_return": _APEX_INPUTS, "stance": _STANCE_INPUTS}


def _param(name: str, row: dict) -> Quantity:
    default = f" (default {row['default']})" if isinstance(row.get("default"), str) else ""
    return Quantity(name, row["unit"], row["doc"] + default, "param", positive)


#: The parameters (``derive/params.py``: the fields, then the aliases), and the stiffness ratio.
_PARAMS = (
    *(_param(r["name"], r) for r in _table.PARAMETERS[:2]),
    *(_param(name, a) for name, a in _table.ALIASES.items()),
    *(_param(r["name"], r) for r in _table.PARAMETERS[2:]),
    Quantity(RATIO, "1", "stiffness ratio k_d/k_c (k_d = k_c * ratio)", "param", positive),
)


def quantities(kind: str) -> dict[str, Quantity]:
    """Every quantity a sweep of ``kind`` can vary or fix, by name: its inputs, then the parameters
    (a stance sweep's ``q_r_td`` is its touchdown input)."""
    if kind not in KINDS:
        raise ValueError(f"sweep kind must be one of {', '.join(map(repr, KINDS))}, got {kind!r}")
    out = {q.name: q for q in KINDS[kind]}
    for q in _PARAMS:
        out.setdefault(q.name, q)
    return out


def _number(where: str, value: object) -> float:
    if isinstance(value, (str, bytes, bool)):
        raise ValueError(f"{where} must be a number, got {value!r}")
    return real(where, value)


#: The keys of an axis given as a mapping: a range (low, high, num, scale) or a list of values.
AXIS_KEYS = ("low", "high", "num", "scale", "values")


@dataclass(frozen=True)
class Axis:
    """One swept quantity: ``values`` (a list), or a range ``low``..``high`` with ``num`` grid points
    (``scale`` "linear" or "log"). A random sweep ignores ``num``."""

    name: str
    values: tuple[float, ...] | None = None
    low: float | None = None
    high: float | None = None
    num: int | None = None
    scale: str = "linear"

    @classmethod
    def of(cls, name: str, spec: object) -> Axis:
        """An axis from a Python or TOML value: an :class:`Axis`, a mapping ``{low, high, num, scale}``,
        a sequence (or array) of values, or a command-line string ``LOW:HIGH[:NUM[:log]]`` /
        ``V1,V2,...``. ValueError naming the axis when malformed."""
        where = f"axis {name!r}"
        if isinstance(spec, Axis):
            return cls.of(name, spec.as_dict())
        if isinstance(spec, str):
            return cls.of(name, _parse_text(where, spec))
        if isinstance(spec, Mapping):
            unknown = set(spec) - set(AXIS_KEYS)
            if unknown:
                raise ValueError(
                    f"{where}: unknown key(s) {', '.join(sorted(unknown))}; the keys are "
                    f"{', '.join(AXIS_KEYS)}"
                )
            if "values" in spec:
                if set(spec) != {"values"}:
                    raise ValueError(f"{where}: give either values or low/high/num, not both")
                return cls.of(name, spec["values"])
            if "low" not in spec or "high" not in spec:
                raise ValueError(f"{where}: a range needs low and high (and num on a grid)")
            low, high = _number(f"{where} low", spec["low"]), _number(f"{where} high", spec["high"])
            if high < low:
                raise ValueError(f"{where}: high must not be below low, got low={low!r}, high={high!r}")
            num = spec.get("num")
            if num is not None:
                if isinstance(num, bool) or not isinstance(num, (int, np.integer)) or num < 1:
                    raise ValueError(f"{where} num must be a positive whole number, got {num!r}")
                num = int(num)
                if num == 1 and high != low:
                    raise ValueError(f"{where}: num = 1 needs low == high (use a value list for one point)")
            scale = spec.get("scale", "linear")
            if scale not in ("linear", "log"):
                raise ValueError(f"{where} scale must be 'linear' or 'log', got {scale!r}")
            if scale == "log" and low <= 0.0:
                raise ValueError(f"{where}: a log scale needs low > 0, got {low!r}")
            return cls(name, None, low, high, num, scale)
        if isinstance(spec, (Sequence, np.ndarray)) and not isinstance(spec, (bytes, bytearray)):
            values = tuple(_number(f"{where} value", v) for v in np.asarray(spec, dtype=object).ravel())
            if not values:
                raise ValueError(f"{where}: an empty list of values")
            return cls(name, values)
        raise ValueError(
            f"{where} must be a list of values or a range {{low, high, num}}, "
            f"got {type(spec).__name__}: {spec!r}"
        )

    @property
    def grid_size(self) -> int | None:
        """The number of grid points, or None for a range without ``num`` (usable only in a random sweep)."""
        return len(self.values) if self.values is not None else self.num

    def bounds(self) -> tuple[float, float]:
        """The smallest and the largest value."""
        if self.values is not None:
            return min(self.values), max(self.values)
        return self.low, self.high

    def check_grid(self) -> None:
        """ValueError for a range without ``num`` (usable only in a random sweep)."""
        if self.values is None and self.num is None:
            raise ValueError(f"axis {self.name!r}: a grid needs num (the number of points on low..high)")

    def grid_values(self) -> np.ndarray:
        """Every grid value (``num`` of them: for small axes; a sweep takes :meth:`grid_at`)."""
        self.check_grid()
        return self.grid_at(np.arange(self.grid_size, dtype=np.int64))

    def grid_at(self, index: np.ndarray) -> np.ndarray:
        """The grid values at the point indices ``index`` (0 .. grid_size - 1), computed from the
        indices alone (never the whole axis: ``num`` may be 10^11) and bit for bit
        ``numpy.linspace(low, high, num)[index]`` (``numpy.geomspace`` on a log scale)."""
        self.check_grid()
        index = np.asarray(index, dtype=np.int64)
        if self.values is not None:
            return np.asarray(self.values, dtype=float)[index]
        if self.scale == "log":
            log_low, log_high = np.log10(np.float64(self.low)), np.log10(np.float64(self.high))
            y = np.power(10.0, _linspace_at(log_low, log_high, self.num, index))
            y[index == 0] = self.low
        else:
            y = _linspace_at(self.low, self.high, self.num, index)
        if self.num > 1:
            y[index == self.num - 1] = self.high
        return y

    def draw(self, u: np.ndarray) -> np.ndarray:
        """Values for uniform doubles ``u`` in [0, 1): uniform (log-uniform) on the range, or uniform
        over the listed values."""
        if self.values is not None:
            vals = np.asarray(self.values, dtype=float)
            return vals[np.minimum((u * len(vals)).astype(np.int64), len(vals) - 1)]
        if self.scale == "log":
            lo, hi = math.log(self.low), math.log(self.high)
            return np.exp(lo + u * (hi - lo))
        return self.low + u * (self.high - self.low)

    def check(self, quantity: Quantity) -> None:
        """ValueError when a value (or an end of the range) lies outside the quantity's domain (all
        domains are intervals, so the ends of a range suffice)."""
        ends = self.values if self.values is not None else (self.low, self.high)
        for v in ends:
            quantity.check(f"axis {self.name}", v)

    def as_dict(self) -> dict:
        if self.values is not None:
            return {"values": list(self.values)}
        d = {"low": self.low, "high": self.high}
        if self.num is not None:
            d["num"] = self.num
        if self.scale != "linear":
            d["scale"] = self.scale
        return d


def _linspace_at(low: float, high: float, num: int, index: np.ndarray) -> np.ndarray:
    """``numpy.linspace(low, high, num)[index]`` by numpy's own arithmetic (index * step + low; the
    last point is ``high``, which the caller sets), without the other points."""
    i = index.astype(np.float64)
    delta = np.float64(high) - np.float64(low)
    div = num - 1
    if div > 0:
        step = delta / div
        y = i / div * delta if step == 0 else i * step  # numpy's branch for a denormal step
    else:
        y = i * delta
    return y + np.float64(low)


def _parse_text(where: str, text: str) -> dict:
    """``LOW:HIGH[:NUM[:log]]`` -> a range, ``V1,V2,...`` (or one value) -> values."""
    parts = [p.strip() for p in text.split(":")]

    def num(s: str) -> float:
        try:
            return float(s)
        except ValueError:
            raise ValueError(f"{where}: {s!r} is not a number (LOW:HIGH[:NUM[:log]] or V1,V2,...)") from None

    if len(parts) == 1:
        return {"values": [num(s) for s in text.split(",")]}
    if not 2 <= len(parts) <= 4:
        raise ValueError(f"{where}: expected LOW:HIGH[:NUM[:log]], got {text!r}")
    spec: dict = {"low": num(parts[0]), "high": num(parts[1])}
    if len(parts) >= 3 and parts[2]:
        count = num(parts[2])
        if count != int(count):
            raise ValueError(f"{where}: NUM must be a whole number, got {parts[2]!r}")
        spec["num"] = int(count)
    if len(parts) == 4:
        spec["scale"] = parts[3]
    return spec


def grid_points(axes: Sequence[Axis], start: int, stop: int) -> dict[str, np.ndarray]:
    """The axis values of grid rows ``start..stop-1`` (C order over ``axes``, the last fastest)."""
    idx = np.arange(start, stop, dtype=np.int64)
    if not axes:
        return {}
    shape = tuple(a.grid_size for a in axes)
    multi = np.unravel_index(idx, shape)
    return {a.name: a.grid_at(m) for a, m in zip(axes, multi, strict=True)}


def random_points(axes: Sequence[Axis], seed: int, start: int, stop: int) -> dict[str, np.ndarray]:
    """The axis values of random rows ``start..stop-1``: row ``i``, axis ``j`` from double
    ``i * len(axes) + j`` of ``Philox(key=seed)`` (Philox draws four 64-bit words per counter step,
    one word per double)."""
    d = len(axes)
    if not d:
        return {}
    first = start * d
    bits = np.random.Philox(key=seed)
    bits.advance(first // 4)
    gen = np.random.Generator(bits)
    gen.random(first % 4)
    u = gen.random((stop - start) * d).reshape(stop - start, d)
    return {a.name: a.draw(u[:, j]) for j, a in enumerate(axes)}
