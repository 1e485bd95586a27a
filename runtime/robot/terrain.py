"""The robot's ground: absolute levels per segment of x, simulated as a heightfield, boxes or a plane.

``Terrain(levels, spacing)``: segment i covers ``[i * spacing, (i + 1) * spacing)`` [m] at the
absolute height ``levels[i]`` [m]; the ground is at 0 before x = 0 and stays at the last level after
the last segment. Kinds:

- ``"ramps"`` (default): a MuJoCo heightfield, the levels joined by linear ramps ``ramp`` [m] wide
  centred on the segment boundaries (``0 < ramp <= spacing``), sampled every ``resolution`` [m]
  (the ramps' corners lie on the samples when ``spacing`` and ``ramp / 2`` are multiples of it);
- ``"boxes"``: one box geom per run of equal levels, vertical steps at the boundaries;
- ``"flat"``: a plane at height 0 (no levels). Ground that is 0 everywhere is a plane whatever the
  kind.

The ground covers x in ``[-margin, len(levels) * spacing + margin]`` (:attr:`Terrain.extent`; a
plane everywhere); beyond it there is none. :meth:`Terrain.height_at` (vectorised) is exact for the
shape simulated: the heightfield's samples as MuJoCo stores them (float32, interpolated linearly),
the boxes' tops.
"""

from __future__ import annotations

import math

import numpy as np

from ..api.numeric import is_real, num
from .mj import numbers

__all__ = ["KINDS", "Terrain"]

KINDS = ("ramps", "boxes", "flat")
#: Depth of the heightfield's and the boxes' base below the lowest level [m].
_BASE = 1.0


class Terrain:
    """The ground (module docstring). ``levels`` [m] per segment of ``spacing`` [m]; ``kind`` one of
    :data:`KINDS`; ``ramp`` [m] the ramps' width; ``resolution`` [m] the heightfield's sample
    spacing; ``margin`` [m] the ground beyond the first and the last segment."""

    def __init__(
        self,
        levels=(),
        spacing: float = 1.0,
        kind: str = "ramps",
        ramp: float = 0.1,
        resolution: float = 0.01,
        margin: float = 20.0,
    ):
        problems = []
        try:
            lv = np.asarray(levels, dtype=float).reshape(-1)
        except (TypeError, ValueError):
            lv = None
            problems.append(f"Terrain.levels must be a sequence of finite heights [m], got {levels!r}")
        if lv is not None and not np.isfinite(lv).all():
            problems.append(f"Terrain.levels must be finite heights [m], got {lv.tolist()!r}")
        for name, value in (("spacing", spacing), ("ramp", ramp), ("resolution", resolution)):
            if not (is_real(value) and math.isfinite(value) and value > 0):
                problems.append(f"Terrain.{name} [m] must be finite and > 0, got {num(value)}")
        if not (is_real(margin) and math.isfinite(margin) and margin >= 0):
            problems.append(f"Terrain.margin [m] must be finite and >= 0, got {num(margin)}")
        if kind not in KINDS:
            problems.append(f"Terrain.kind must be one of {', '.join(map(repr, KINDS))}, got {kind!r}")
        if not problems and kind == "ramps" and ramp > spacing:
            problems.append(f"Terrain.ramp [m] must be <= spacing = {num(spacing)}, got {num(ramp)}")
        if not problems and kind == "flat" and np.any(lv != 0):
            problems.append("Terrain.levels must be empty or 0 for kind 'flat' (a plane at 0)")
        if problems:
            raise ValueError("\n".join(problems))
        self.levels = lv
        self.spacing = float(spacing)
        self.ramp = float(ramp)
        self.resolution = float(resolution)
        self.margin = float(margin)
        self.kind = "flat" if not np.any(lv != 0) else kind
        self.extent = (
            (-math.inf, math.inf)
            if self.kind == "flat"
            else (-self.margin, lv.size * self.spacing + self.margin)
        )
        if self.kind == "ramps":
            self._x, self._h = self._samples()
        elif self.kind == "boxes":
            self._edges, self._tops = self._runs()

    @classmethod
    def flat(cls) -> Terrain:
        """Flat ground at height 0 (a plane)."""
        return cls((), kind="flat")

    def __repr__(self) -> str:
        return (
            f"Terrain({len(self.levels)} levels, spacing={self.spacing}, kind={self.kind!r}, "
            f"ramp={self.ramp}, resolution={self.resolution})"
        )

    # ------------------------------------------------------------------------------------------
    def _ideal(self, x: np.ndarray) -> np.ndarray:
        """The ramps' ideal profile: levels joined by ramps ``ramp`` wide centred on the boundaries."""
        n = self.levels.size
        before = np.concatenate([[0.0], self.levels])  # level left of boundary i (i = 0..n-1)
        knots_x, knots_h = [], []
        half = 0.5 * self.ramp
        for i in range(n):
            b = i * self.spacing
            knots_x += [b - half, b + half]
            knots_h += [before[i], self.levels[i]]
        return np.interp(x, knots_x, knots_h)

    def _samples(self):
        """The heightfield's sample positions and heights as MuJoCo stores them (float32, normalised
        to [0, 1] of the elevation range above the lowest level)."""
        x0, x1 = self.extent
        ncol = int(math.ceil((x1 - x0) / self.resolution - 1e-9)) + 1
        x1 = x0 + (ncol - 1) * self.resolution
        self.extent = (x0, x1)
        x = x0 + self.resolution * np.arange(ncol)
        ideal = self._ideal(x)
        low, high = min(0.0, ideal.min()), max(0.0, ideal.max())
        self._low, self._rise = low, max(high - low, 1e-6)
        self._data = ((ideal - low) / self._rise).astype(np.float32)
        stored = self._low + self._rise * self._data.astype(np.float64)
        return x, stored

    def _runs(self):
        """The boxes: edges of runs of equal levels (level 0 before x = 0) and their tops."""
        x0, x1 = self.extent
        lv = np.concatenate([[0.0], self.levels])
        edges, tops = [x0], [0.0]
        for i in range(1, lv.size):
            if lv[i] != tops[-1]:
                edges.append((i - 1) * self.spacing)
                tops.append(lv[i])
        edges.append(x1)
        return np.array(edges), np.array(tops)

    # ------------------------------------------------------------------------------------------
    def height_at(self, x):
        """The ground's height [m] at ``x`` [m] (array-like; NaN outside :attr:`extent`), exact for
        the simulated shape."""
        xa = np.asarray(x, dtype=float)
        if self.kind == "flat":
            h = np.zeros_like(xa)
        elif self.kind == "ramps":
            h = np.interp(xa, self._x, self._h)
        else:
            i = np.clip(np.searchsorted(self._edges, xa, side="right") - 1, 0, self._tops.size - 1)
            h = self._tops[i]
        h = np.where((xa >= self.extent[0]) & (xa <= self.extent[1]), h, np.nan)
        return h if h.ndim else float(h)

    # ------------------------------------------------------------------------------------------
    def assets_xml(self) -> str:
        """The MJCF ``<asset>`` children (the heightfield's declaration)."""
        if self.kind != "ramps":
            return ""
        x0, x1 = self.extent
        rx = 0.5 * (x1 - x0)
        size = numbers(rx, 0.5, self._rise, _BASE)
        return f'<hfield name="terrain" nrow="2" ncol="{self._x.size}" size="{size}"/>'

    def geoms_xml(self, attrs: str) -> str:
        """The MJCF ``<worldbody>`` geoms of the ground, each with the contact attributes ``attrs``."""
        if self.kind == "flat":
            return f'<geom name="ground" type="plane" size="0 0 1" {attrs}/>'
        if self.kind == "ramps":
            x0, x1 = self.extent
            cx = 0.5 * (x0 + x1)
            pos = numbers(cx, 0, self._low)
            return f'<geom name="ground" type="hfield" hfield="terrain" pos="{pos}" {attrs}/>'
        bottom = min(0.0, float(self.levels.min())) - _BASE
        out = []
        for j, top in enumerate(self._tops):
            a, b = self._edges[j], self._edges[j + 1]
            hx, hz = 0.5 * (b - a), 0.5 * (top - bottom)
            out.append(
                f'<geom name="ground{j}" type="box" size="{numbers(hx, 0.5, hz)}" '
                f'pos="{numbers(0.5 * (a + b), 0, 0.5 * (top + bottom))}" {attrs}/>'
            )
        return "\n".join(out)

    def load(self, model) -> None:
        """Write the heightfield's samples into a compiled ``mujoco.MjModel`` (rows along y equal)."""
        if self.kind == "ramps":
            model.hfield_data[:] = np.tile(self._data, 2)
