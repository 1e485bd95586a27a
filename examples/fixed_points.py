"""Periodic running gaits from the exact and the approximate apex-return maps.

For apex speeds 3-7 m/s at apex height 1.0 m, the touchdown angle that returns the runner to the
same apex height (a fixed point of the apex-return map for k_c = k_d, g_s = g_f) is found with
``scipy.optimize.brentq``, with the exact map and with each map given on the command line (default:
Geyer et al.'s and gravity type 5). A sweep over 20,000 angles per speed with the parallel batch
API brackets the root. A periodic gait is symmetric, Geyer et al.'s setting, so its angle is close
to the exact one; the corrections are compared there too.

Run: ``python examples/fixed_points.py [MAP ...]``.
"""

from __future__ import annotations

import sys

import numpy as np
import slipmaps
from scipy.optimize import brentq

PARAMS = slipmaps.HUMAN_RUNNER
HEIGHT = 1.0


def bracket(name: str, speed: float) -> tuple[float, float] | None:
    """A sign change of next height - height over a fine angle sweep with the batch map."""
    angles = np.linspace(0.15, 0.7, 20_000)
    res = slipmaps.apex_return_batch(name, PARAMS, HEIGHT, speed, angles)
    gap = np.where(res.ok, res["apex_height"] - HEIGHT, np.nan)
    idx = np.flatnonzero(np.sign(gap[:-1]) * np.sign(gap[1:]) < 0)
    return (angles[idx[0]] - 0.05, angles[idx[0] + 1] + 0.05) if idx.size else None


def fixed_point(name: str, speed: float, br: tuple[float, float]) -> float:
    def gap(angle: float) -> float:
        return slipmaps.apex_return(name, PARAMS, HEIGHT, speed, angle).apex_height - HEIGHT

    return brentq(gap, *br, xtol=1e-12)


def main(names: list[str]) -> None:
    print(f"periodic gaits, apex height {HEIGHT} m: touchdown angle [rad] (difference to exact)")
    print(f"{'speed':>6} {'exact':>10}" + "".join(f" {n:>26}" for n in names))
    for speed in np.arange(3.0, 7.01, 1.0):
        br = bracket(names[0], speed)
        if br is None:
            print(f"{speed:6.1f}  no periodic gait found")
            continue
        try:
            exact = fixed_point("exact", speed, br)
            cells = [fixed_point(n, speed, br) for n in names]
        except ValueError as exc:  # no sign change inside the widened bracket
            print(f"{speed:6.1f}  {exc}")
            continue
        print(f"{speed:6.1f} {exact:10.6f}" + "".join(f" {a:12.6f} ({a - exact:+10.2e})" for a in cells))


if __name__ == "__main__":
    main(sys.argv[1:] or ["geyer", "gravity-type5"])
