"""The step grids of the accuracy study (``slipmaps accuracy``), each a parameter set and apex points.

- ``nonsymmetric``: apex speeds x touchdown angles x apex heights; the apex height sets the
  touchdown vertical speed, so most steps are nonsymmetric (liftoff does not mirror touchdown).
  The hard corner is slow speed with a flat leg: a large sweep, where gravity changes the angular
  momentum most.
- ``symmetric``: for each apex speed and height, the touchdown angle at which the exact stance is
  symmetric (bottom at q_th = 0, so liftoff mirrors touchdown), found by root-finding on the exact
  bottom angle; Geyer et al.'s setting (Assumption 1 holds best there).
- ``yu``: the protocol of Yu, Li and Cai (ICRA 2012): m = 80 kg, l0 = 1 m, k l0/(m g) = 10, apex
  height 0.95-1.05 m, apex speed 2-6 m/s, angle of attack 60, 65, 68, 72 degrees from the ground
  (q_th_td = 90 deg - angle of attack).

Parameter sets: the human runner (k l0/(m g) = 25.5), the robot hopper (12.7) at the same Froude
numbers v / sqrt(g l0) and apex heights in leg lengths.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from ..api.progress import progress
from ..exact.reference import simulate_step

__all__ = ["Grid", "GRIDS", "YU_PARAMS", "YU_ANGLES_DEG", "equispaced", "symmetric_angle"]

#: Yu, Li and Cai (ICRA 2012): k l0 / (m g) = 10.
YU_PARAMS = SlipParams(m=80.0, l0=1.0, k=10.0 * 80.0 * 9.81 / 1.0)
#: Angles of attack from the ground, degrees.
YU_ANGLES_DEG = (60.0, 65.0, 68.0, 72.0)


def equispaced(start: float, step: float, n: int) -> tuple[float, ...]:
    """``n`` equispaced values, rounded so that they print exactly (0.30, not 0.30000000000000004)."""
    return tuple(round(start + i * step, 10) for i in range(n))


@dataclass(frozen=True)
class Grid:
    """A parameter set and its apex points (height [m], speed [m/s], touchdown angle [rad])."""

    name: str
    kind: str  # "nonsymmetric", "symmetric" or "yu"
    params: SlipParams
    heights: tuple[float, ...]
    speeds: tuple[float, ...]
    angles: tuple[float, ...] = ()  # touchdown angles [rad]; found per point for "symmetric"
    description: str = ""

    def points(self, show_progress: bool | None = None) -> np.ndarray:
        """(n, 3) array of (apex height, apex speed, touchdown angle), row-major over the axes.

        For a symmetric grid, the angle of each (height, speed) is the root of the exact bottom
        angle (NaN where there is none in (0, 1.2) rad), found once per grid and process (the
        accuracy and stiffness studies share them).
        """
        if self.kind != "symmetric":
            return np.array([(h, v, a) for a in self.angles for h in self.heights for v in self.speeds])
        if self not in _SYMMETRIC_POINTS:
            pairs = [(h, v) for h in self.heights for v in self.speeds]
            rows = [
                (h, v, symmetric_angle(self.params, h, v))
                for h, v in progress(pairs, len(pairs), f"symmetric gaits ({self.name})", show_progress)
            ]
            _SYMMETRIC_POINTS[self] = np.array(rows)
        return _SYMMETRIC_POINTS[self].copy()


#: The points of each symmetric grid, found once (root-finding on exact steps: about 0.1 s a point).
_SYMMETRIC_POINTS: dict[Grid, np.ndarray] = {}


def _bottom_angle(params: SlipParams, h: float, v: float, angle: float) -> float:
    step = simulate_step(params, h, v, angle)
    return step.bottom[2] if step.bottom is not None else math.nan


def symmetric_angle(params: SlipParams, h: float, v: float, lo: float = 0.02, hi: float = 1.2) -> float:
    """The touchdown angle whose exact stance has its bottom at q_th = 0 (NaN if none in (lo, hi)).

    The bottom angle grows with the touchdown angle; the first sign change on a 0.04 rad scan is
    refined by Brent's method to 1e-12 rad.
    """
    scan = np.arange(lo, hi, 0.04)
    values = [_bottom_angle(params, h, v, a) for a in scan]
    for a0, a1, f0, f1 in zip(scan[:-1], scan[1:], values[:-1], values[1:], strict=True):
        if math.isfinite(f0) and math.isfinite(f1) and f0 < 0.0 <= f1:
            return float(brentq(lambda a: _bottom_angle(params, h, v, a), a0, a1, xtol=1e-12, rtol=1e-12))
    return math.nan


def _human_and_hopper() -> tuple[Grid, ...]:
    out = []
    for label, p, angles in (
        ("human runner", HUMAN_RUNNER, equispaced(0.30, 0.025, 9)),
        ("robot hopper", ROBOT_HOPPER, equispaced(0.40, 0.025, 9)),
    ):
        scale = p.l0 / HUMAN_RUNNER.l0
        froude = math.sqrt(scale)
        out.append(
            Grid(
                f"{label}, nonsymmetric",
                "nonsymmetric",
                p,
                heights=tuple(round(f * p.l0, 10) for f in (1.0, 1.05, 1.15)),
                speeds=tuple(round(v * froude, 10) for v in equispaced(3.0, 0.5, 9)),
                angles=angles,
                description="apex height (1.0, 1.05, 1.15) l0, 9 apex speeds, 9 touchdown angles",
            )
        )
        out.append(
            Grid(
                f"{label}, symmetric",
                "symmetric",
                p,
                heights=tuple(round(f * p.l0, 10) for f in (1.0, 1.05, 1.1)),
                speeds=tuple(round(v * froude, 10) for v in equispaced(3.0, 1.0, 5)),
                description="apex height (1.0, 1.05, 1.1) l0, 5 apex speeds, the touchdown angle of the "
                "symmetric exact stance",
            )
        )
    return tuple(out)


#: The grids of ``slipmaps accuracy``, in report order.
GRIDS: tuple[Grid, ...] = (
    *_human_and_hopper(),
    Grid(
        "Yu, Li and Cai protocol",
        "yu",
        YU_PARAMS,
        heights=equispaced(0.95, 0.025, 5),
        speeds=equispaced(2.0, 0.25, 17),
        angles=tuple(round(math.radians(90.0 - a), 12) for a in YU_ANGLES_DEG),
        description="m = 80 kg, l0 = 1 m, k = 7848 N/m (k l0/(m g) = 10); apex height 0.95-1.05 m (5), apex "
        "speed 2-6 m/s (17), angle of attack 60, 65, 68, 72 deg from the ground",
    ),
)
