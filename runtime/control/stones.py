"""Stepping stones: a course of footholds with gaps between them (``[terrain] kind = "stones"``).

A :class:`Course` is a row of stones along x, each an interval [x_a, x_b] [m] at a height [m], and
a ``margin`` [m]: the foot must land at least ``margin`` inside a stone's ends (a real foot has a
size, a stone's edge crumbles), on the stone's *usable part* [x_a + margin, x_b - margin]. Positions
are absolute: x from the start apex (x = 0), heights from the ground under the start apex (0). The
stones are sorted along x and do not overlap (two may touch); gaps between them have no ground.

Where a foot lands (:meth:`Course.landing`): on the stone whose usable part holds its x, else
nowhere: a *miss*, which ends a run there with the plant status :data:`MISSED` (a run's own
plant status beside the plant's :class:`~slipmaps.Status` codes; its name ``"MISSED"``). The
ground under a touchdown is the height of the stone the foot meets: falling from the apex, the foot
meets the highest stone whose interval holds the foot's x when the foot is at that stone's height
(:func:`met`; a stone's sides are not modelled).

A course is listed by hand (``stones = [[x_a, x_b, height], ...]`` in TOML, :meth:`Course.of`) or
drawn by :func:`random_course`, seeded, as Rutschmann, Satzinger, Byl and Byl (2012) draw theirs:
the widths, the gaps and the height changes between consecutive stones uniform in their ranges, the
first stone at height 0 from x = 0 (under the start apex). A bad course is refused with one line
naming the stone (:class:`CourseError`, a ValueError): stones that overlap or are out of order, a
stone no wider than twice the margin (no usable part), a value that is not finite.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..api.numeric import is_real, num

__all__ = ["Course", "CourseError", "LOOKAHEAD", "MISSED", "met", "random_course"]

#: The plant status of a step whose foot landed outside every stone's usable part (a miss): a run's
#: own code, far above the kernels' :class:`~slipmaps.Status` codes (which are appended from 0 on).
MISSED = 100
#: Its name and meaning.
MISSED_NAME = "MISSED"
MISSED_MESSAGE = "the foot landed outside every stone's usable part (a miss): the runner falls there"
#: The stones a controller sees ahead by default (a scenario's ``lookahead``, the planner's).
LOOKAHEAD = 10


class CourseError(ValueError):
    """A course that cannot be hopped, one line naming the stone (module docstring)."""


@dataclass(frozen=True)
class Course:
    """Stones (module docstring): their ends ``x_a``, ``x_b`` [m] and ``height`` [m] (tuples of
    floats, sorted along x), and the ``margin`` [m] every foot keeps from a stone's ends. Build it
    with :meth:`Course.of` (validated); ``len(course)`` is the number of stones."""

    x_a: tuple[float, ...]
    x_b: tuple[float, ...]
    height: tuple[float, ...]
    margin: float = 0.0

    def __post_init__(self):
        _validate(self)

    @classmethod
    def of(cls, stones, margin: float = 0.0, where: str = "stones") -> Course:
        """A course from ``stones`` (a :class:`Course`, whose margin ``margin`` replaces, or a
        sequence of ``[x_a, x_b, height]``) and ``margin``; a ValueError (``CourseError``) naming
        ``where`` and the stone."""
        if isinstance(stones, Course):
            return cls(stones.x_a, stones.x_b, stones.height, _margin(margin, where))
        try:
            rows = [list(s) for s in stones]
        except TypeError:
            raise CourseError(f"{where} must be a list of [x_a, x_b, height] [m], got {stones!r}") from None
        for i, row in enumerate(rows):
            if len(row) != 3:
                raise CourseError(f"{where}[{i}] must be [x_a, x_b, height] [m], got {row!r}")
            bad = next((x for x in row if not (is_real(x) and math.isfinite(x))), None)
            if bad is not None:
                raise CourseError(f"{where}[{i}] must hold finite numbers [m], got {num(bad)}")
        try:
            return cls(
                tuple(float(r[0]) for r in rows),
                tuple(float(r[1]) for r in rows),
                tuple(float(r[2]) for r in rows),
                _margin(margin, where),
            )
        except CourseError as exc:
            raise CourseError(f"{where}: {exc}") from None

    def __len__(self) -> int:
        return len(self.x_a)

    @cached_property
    def lo(self) -> np.ndarray:
        """The usable parts' starts, x_a + margin [m]."""
        return np.asarray(self.x_a) + self.margin

    @cached_property
    def hi(self) -> np.ndarray:
        """The usable parts' ends, x_b - margin [m]."""
        return np.asarray(self.x_b) - self.margin

    @cached_property
    def heights(self) -> np.ndarray:
        return np.asarray(self.height)

    @cached_property
    def table(self) -> np.ndarray:
        """An array (n, 6), the stones as the footholds solver reads them; per stone its usable
        part's ends, centre and half-width, its height, the next stone's height (the last one's
        own)."""
        lo, hi, y = self.lo, self.hi, self.heights
        nxt = np.append(y[1:], y[-1])
        return np.ascontiguousarray(np.stack([lo, hi, 0.5 * (lo + hi), 0.5 * (hi - lo), y, nxt], axis=1))

    @property
    def end(self) -> float:
        """The last stone's end [m]."""
        return self.x_b[-1]

    def ahead(self, x, count: int) -> np.ndarray:
        """The indices of the next ``count`` stones whose usable part ends beyond ``x`` [m] (the
        stones a controller at an apex over ``x`` sees: ``lookahead``), in order."""
        first = int(np.searchsorted(self.hi, float(x), side="right"))
        return np.arange(first, min(first + int(count), len(self)))

    def landing(self, x) -> np.ndarray:
        """The stone whose usable part holds each foot position ``x`` [m] (array-like), -1 where
        none does (a miss)."""
        xs = np.atleast_1d(np.asarray(x, dtype=float))
        i = np.searchsorted(self.lo, xs, side="right") - 1
        j = np.clip(i, 0, len(self) - 1)
        inside = (i >= 0) & (xs <= self.hi[j]) & np.isfinite(xs)
        return np.where(inside, j, -1)

    def gaps(self) -> np.ndarray:
        """The gaps between consecutive stones [m] (len - 1)."""
        return np.asarray(self.x_a[1:]) - np.asarray(self.x_b[:-1])

    def polyline(self, depth: float = 0.3) -> np.ndarray:
        """The course drawn as a polyline (k, 2): each stone's top, the gaps ``depth`` [m] below the
        lowest stone."""
        pit = min(self.height) - depth
        pts = []
        for a, b, y in zip(self.x_a, self.x_b, self.height, strict=True):
            pts += [(a, pit), (a, y), (b, y), (b, pit)]
        return np.array(pts)

    def as_list(self) -> list[list[float]]:
        """``[[x_a, x_b, height], ...]`` (as in TOML)."""
        return [[a, b, y] for a, b, y in zip(self.x_a, self.x_b, self.height, strict=True)]

    def as_dict(self) -> dict:
        return {"stones": self.as_list(), "margin": self.margin}


def _margin(margin, where: str) -> float:
    if not (is_real(margin) and math.isfinite(margin) and margin >= 0.0):
        raise CourseError(f"{where}: margin must be a finite number >= 0 [m], got {num(margin)}")
    return float(margin)


def _validate(c: Course) -> None:
    """One line for the first problem: no stone, a stone with x_b <= x_a, stones out of order or
    overlapping, a margin that leaves a stone no usable part."""
    n = len(c.x_a)
    if n == 0:
        raise CourseError("a course needs at least one stone")
    if not (len(c.x_b) == len(c.height) == n):
        raise CourseError(f"x_a, x_b and height must have one value per stone, got {n}, {len(c.x_b)}, "
                          f"{len(c.height)}")  # fmt: skip
    for i in range(n):
        a, b = c.x_a[i], c.x_b[i]
        if not b > a:
            raise CourseError(f"stone {i} must have x_b > x_a, got [{num(a)}, {num(b)}]")
        if b - a <= 2.0 * c.margin:
            raise CourseError(
                f"stone {i} ([{num(a)}, {num(b)}] m, {b - a:.6g} m wide) has no usable part: the margin "
                f"{num(c.margin)} m on either end needs it wider than {2.0 * c.margin:.6g} m"
            )
        if i and a < c.x_b[i - 1]:
            raise CourseError(
                f"stone {i} ([{num(a)}, {num(b)}] m) overlaps stone {i - 1} ([{num(c.x_a[i - 1])}, "
                f"{num(c.x_b[i - 1])}] m): stones are listed along x, each starting where the last ends "
                "or after"
            )


def random_course(
    seed: int = 0,
    *,
    count: int = 60,
    width: tuple[float, float] = (0.3, 0.6),
    gap: tuple[float, float] = (0.2, 0.8),
    rise: float = 0.0,
    margin: float = 0.0,
    first: float | None = None,
) -> Course:
    """A seeded random course (module docstring): ``count`` stones, widths uniform in ``width`` [m],
    gaps uniform in ``gap`` [m], each stone's height its predecessor's plus a change uniform in
    +-``rise`` [m]; the first stone at height 0 from x = 0, ``first`` [m] wide (default: a width
    drawn as the others'). Edges and heights rounded to the millimetre."""
    for name, pair, low in (("width", width, 0.0), ("gap", gap, 0.0)):
        try:
            a, b = (float(x) for x in pair)
        except (TypeError, ValueError):
            raise CourseError(f"{name} must be a pair [low, high] [m], got {pair!r}") from None
        if not (math.isfinite(a) and math.isfinite(b) and low <= a <= b and (name == "gap" or a > 0)):
            raise CourseError(f"{name} must be [low, high] [m] with {low:g} <= low <= high, got {pair!r}")
    if not (is_real(rise) and math.isfinite(rise) and rise >= 0.0):
        raise CourseError(f"rise must be a finite number >= 0 [m], got {num(rise)}")
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 1:
        raise CourseError(f"count must be a whole number >= 1, got {count!r}")
    rng = np.random.default_rng(seed)
    widths = rng.uniform(*width, count)
    gaps = rng.uniform(*gap, count)
    changes = rng.uniform(-rise, rise, count)
    if first is not None:
        widths[0] = first
    x, y, rows = 0.0, 0.0, []
    for i in range(count):
        a = round(x, 3)
        b = round(x + widths[i], 3)
        rows.append((a, b, round(y, 3)))
        x = b + gaps[i]
        y = y + changes[i]
    return Course.of(rows, margin)


def met(course: Course, candidates: np.ndarray, foot: np.ndarray) -> np.ndarray:
    """The stone a falling foot meets (module docstring), a row per foot: of the ``candidates``
    (indices, (n, k); -1 for none), the highest whose interval holds ``foot[:, j]``, the foot's x
    when it is at candidate j's height (NaN where it never is); -1 where none does."""
    cand = np.asarray(candidates, dtype=np.int64)
    safe = np.clip(cand, 0, len(course) - 1)
    a, b, y = np.asarray(course.x_a)[safe], np.asarray(course.x_b)[safe], course.heights[safe]
    holds = (cand >= 0) & (foot >= a) & (foot <= b)  # NaN compares False
    best = np.argmax(np.where(holds, y, -np.inf), axis=1)
    rows = np.arange(cand.shape[0])
    return np.where(holds.any(axis=1), cand[rows, best], -1)
