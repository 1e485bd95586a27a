"""Periodic running gaits from the exact and the approximate apex-return maps.

For apex speeds 3-7 m/s at apex height 1.0 m, ``slipmaps.fixed_points`` finds every touchdown angle
whose step returns the human runner to the same apex (a bracketing scan with the batch API, then a
safeguarded Newton method), with the exact map and with each map given on the command line
(default: Geyer et al.'s and gravity type 5), and the eigenvalue of the apex-height return map on
the energy level: the gait is self-stable when its magnitude is below 1 (Seyfarth et al., J Biomech
2002). ``slipmaps gait`` prints the same with more columns; docs/stability.md compares every map.

Run: ``python examples/fixed_points.py [MAP ...]``.
"""

from __future__ import annotations

import sys

import slipmaps

PARAMS = slipmaps.HUMAN_RUNNER
HEIGHT = 1.0
SPEEDS = (3.0, 4.0, 5.0, 6.0, 7.0)


def cell(p) -> str:
    return f"{p.touchdown_angle:.6f} rad, lambda {p.eigenvalue:+.3f}{' (stable)' if p.stable else ''}"


def main(names: list[str]) -> None:
    print(
        f"periodic gaits, apex height {HEIGHT} m: touchdown angle and eigenvalue (angle difference to exact)"
    )
    for speed in SPEEDS:
        exact = slipmaps.fixed_points("exact", PARAMS, apex_height=HEIGHT, speed=speed)
        print(f"{speed:4.1f} m/s  exact: " + ("; ".join(cell(p) for p in exact) or "no periodic gait"))
        for name in names:
            found = slipmaps.fixed_points(name, PARAMS, apex_height=HEIGHT, speed=speed)
            parts = []
            for p in found:
                near = min(exact, key=lambda e: abs(e.touchdown_angle - p.touchdown_angle), default=None)
                diff = f" ({p.touchdown_angle - near.touchdown_angle:+.2e})" if near is not None else ""
                parts.append(cell(p) + diff)
            print(f"{'':9}{name}: " + ("; ".join(parts) or "no periodic gait"))


if __name__ == "__main__":
    main(sys.argv[1:] or ["geyer", "gravity-type5"])
