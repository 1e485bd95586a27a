"""Choose the decompression stiffness k_d at the bottom so that the next apex reaches a target height.

A leg that switches stiffness at the bottom (report section 5: k_c while compressing, k_d after)
controls the energy of the next flight: the switch adds (k_d - k_c)(l0 - q_r_b)^2 / 2 (eq 97). A
controller at the bottom knows the bottom state (here: the exact simulator's, standing in for a
measurement), predicts the next apex for a candidate k_d with a map's decompression half and the
exact flight, and solves next apex height = target for k_d by Newton's method, the derivative by a
central difference on the map: each step is three map calls of about a microsecond.

Two planners are compared: ``iterative-decompression`` (report 5.2.2) from the bottom state, and
``geyer-vs`` (report 5.1), the whole step planned at the apex. The chosen k_d is then checked with
the exact simulator from the same apex: the printed error is what the runner would see.

Run: ``python examples/choose_kd.py [TARGET_HEIGHT ...]`` (default 0.95 1.0 1.05 m).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass

import slipmaps
from slipmaps.runtime.cli.flight import next_apex, touchdown

PARAMS = slipmaps.HUMAN_RUNNER  # k_c = 20000 N/m
APEX = (1.0, 5.0, 0.35)  # apex height [m], apex speed [m/s], touchdown angle [rad]
NEWTON_STEPS = 8
TOL = 1e-9  # [m] on the map's predicted height


@dataclass(frozen=True)
class Choice:
    planner: str
    target: float
    k_d: float
    predicted: float  # next apex height the map predicts for k_d [m]
    exact: float  # next apex height of the exact simulator with k_d [m]
    steps: int


def _with_kd(k_d: float) -> slipmaps.SlipParams:
    return PARAMS.with_(k_d=k_d)


def from_bottom(bottom) -> callable:
    """Next apex height for k_d: the decompression half from ``bottom``, then the exact flight."""

    def height(k_d: float) -> float:
        params = _with_kd(k_d)
        half = slipmaps.half_stance("iterative-decompression", params, bottom)
        if not half.ok:
            return float("nan")
        end = tuple(half[f"end_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd"))
        status, h, _ = next_apex(params, end, 1.0)  # a step toward +x
        return h if status == slipmaps.Status.OK else float("nan")

    return height


def from_apex(k_d: float) -> float:
    """Next apex height for k_d by the simple variable-stiffness map, planned at the apex."""
    return slipmaps.apex_return("geyer-vs", _with_kd(k_d), *APEX).next_apex_height


def newton(height, target: float, k_d: float) -> tuple[float, int]:
    """k_d with height(k_d) = target: Newton's method, central-difference slope on the map."""
    for step in range(1, NEWTON_STEPS + 1):
        gap = height(k_d) - target
        if abs(gap) < TOL:
            return k_d, step - 1
        dk = 1e-4 * k_d
        slope = (height(k_d + dk) - height(k_d - dk)) / (2 * dk)
        k_d -= gap / slope
    return k_d, NEWTON_STEPS


def choose(target: float) -> list[Choice]:
    status, td, _ = touchdown(PARAMS, *APEX)
    assert status == slipmaps.Status.OK
    measured = slipmaps.stance("exact", PARAMS, td)  # the bottom does not depend on k_d
    bottom = measured.bottom
    out = []
    for planner, height in (("iterative-decompression", from_bottom(bottom)), ("geyer-vs", from_apex)):
        k_d, steps = newton(height, target, PARAMS.k_c)
        exact = slipmaps.apex_return("exact", _with_kd(k_d), *APEX).next_apex_height
        out.append(Choice(planner, target, k_d, height(k_d), exact, steps))
    return out


def main(argv: list[str]) -> int:
    targets = [float(x) for x in argv] or [0.95, 1.0, 1.05]
    print(f"apex {APEX[0]} m, {APEX[1]} m/s, touchdown angle {APEX[2]} rad; k_c = {PARAMS.k_c:g} N/m")
    print(
        f"{'target [m]':>10} {'planner':>24} {'k_d [N/m]':>10} {'k_d/k_c':>8} {'map [m]':>10} "
        f"{'exact [m]':>10} {'error [mm]':>10} {'steps':>5}"
    )
    for target in targets:
        for c in choose(target):
            ratio, error_mm = c.k_d / PARAMS.k_c, 1000 * (c.exact - c.target)
            print(
                f"{c.target:10.3f} {c.planner:>24} {c.k_d:10.1f} {ratio:8.3f} {c.predicted:10.6f} "
                f"{c.exact:10.6f} {error_mm:10.3f} {c.steps:5d}"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
