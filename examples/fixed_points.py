"""Periodic running gaits from the exact and the approximate apex-return maps.

For apex speeds 3-7 m/s at apex height 1.0 m, the touchdown angle that returns the runner to the
same apex height (a fixed point of the apex-return map for k_c = k_d, g_s = g_f) is found with
``scipy.optimize.brentq``, once with the exact map (``solve_ivp`` stance) and once with Geyer et
al.'s map. The approximate map's sweep over 20,000 angles per speed uses the parallel batch kernel.

Run: ``python examples/fixed_points.py``.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq
from slipmaps.generated.status import Status
from slipmaps.runtime.apex_maps import apex_return_exact, apex_return_geyer, apex_return_geyer_batch
from slipmaps.runtime.params import HUMAN_RUNNER

HEIGHT = 1.0


def bracket(speed: float) -> tuple[float, float] | None:
    """A sign change of next height - height over a fine angle sweep with the batch map."""
    angles = np.linspace(0.15, 0.7, 20_000)
    out, status = apex_return_geyer_batch(HUMAN_RUNNER, HEIGHT, speed, angles)
    gap = np.where(status == Status.OK, out[:, 0] - HEIGHT, np.nan)
    idx = np.flatnonzero(np.sign(gap[:-1]) * np.sign(gap[1:]) < 0)
    return (angles[idx[0]] - 0.05, angles[idx[0] + 1] + 0.05) if idx.size else None


def main() -> None:
    print(f"{'speed':>6} {'angle exact':>12} {'angle Geyer':>12} {'difference':>11}   [rad]")
    for speed in np.arange(3.0, 7.01, 1.0):
        br = bracket(speed)
        if br is None:
            print(f"{speed:6.1f}  no periodic gait found at apex height {HEIGHT} m")
            continue

        def approx_gap(th: float, v: float = speed) -> float:
            return apex_return_geyer(HUMAN_RUNNER, HEIGHT, v, th).next_apex[0] - HEIGHT

        def exact_gap(th: float, v: float = speed) -> float:
            return apex_return_exact(HUMAN_RUNNER, HEIGHT, v, th).next_apex[0] - HEIGHT

        try:
            th_approx = brentq(approx_gap, *br, xtol=1e-12)
            th_exact = brentq(exact_gap, *br, xtol=1e-12)
        except ValueError as exc:  # no sign change inside the widened bracket on one side
            print(f"{speed:6.1f}  {exc}")
            continue
        print(f"{speed:6.1f} {th_exact:12.6f} {th_approx:12.6f} {th_approx - th_exact:+11.2e}")


if __name__ == "__main__":
    main()
