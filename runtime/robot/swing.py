"""What the robot's low-level controller is told for a descent: the swing leg's angle and the leg's
stiffness as functions of the time since the apex.

A swing is any callable ``swing(t) -> Command`` (t [s] since the apex): the leg's angle from the
vertical [rad] (counterclockwise positive, the foot ahead of the hip for forward running) the hip
servo tracks, and the stiffness k_c, k_d [N/m] the leg would take if it touched down at t (the
robot reads them at the touchdown). Three forms cover the swing-leg policies:

- :func:`hold`: the angle held from the apex;
- :func:`ramp`: ``angle + rate * t`` (a retracting leg: rate [rad/s] < 0 for forward running);
- :func:`table`: angles (and optionally k_c, k_d) at times, interpolated linearly, held after the
  last time (a time-based swing policy).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Command", "hold", "ramp", "table"]


@dataclass(frozen=True)
class Command:
    """The controller's command at one time: ``angle`` [rad], ``k_c`` and ``k_d`` [N/m]."""

    angle: float
    k_c: float
    k_d: float


def _check(name: str, value: float, positive: bool = False) -> float:
    v = float(value)
    if not math.isfinite(v) or (positive and v <= 0):
        raise ValueError(f"swing {name} must be finite{' and > 0' if positive else ''}, got {value!r}")
    return v


def hold(angle: float, k_c: float, k_d: float):
    """The leg at ``angle`` [rad] from the apex on, stiffness ``k_c``, ``k_d`` [N/m]."""
    c = Command(_check("angle", angle), _check("k_c", k_c, True), _check("k_d", k_d, True))
    return lambda t: c


def ramp(angle: float, rate: float, k_c: float, k_d: float):
    """The leg at ``angle + rate * t`` [rad] (``rate`` [rad/s]), stiffness ``k_c``, ``k_d`` [N/m]."""
    a, r = _check("angle", angle), _check("rate", rate)
    kc, kd = _check("k_c", k_c, True), _check("k_d", k_d, True)
    return lambda t: Command(a + r * t, kc, kd)


def table(times, angles, k_c, k_d):
    """Angles [rad] (and k_c, k_d [N/m]: numbers, or one per time) at increasing ``times`` [s],
    linear in between, the first value before the first time and the last after the last."""
    t = np.asarray(times, dtype=float)
    cols = [np.broadcast_to(np.asarray(x, dtype=float), t.shape) for x in (angles, k_c, k_d)]
    if t.ndim != 1 or t.size < 1 or not np.all(np.diff(t) > 0):
        raise ValueError(f"swing times must be one or more increasing times [s], got {times!r}")
    for name, c in zip(("angles", "k_c", "k_d"), cols, strict=True):
        if not np.isfinite(c).all() or (name != "angles" and np.any(c <= 0)):
            raise ValueError(f"swing {name} must be finite{'' if name == 'angles' else ' and > 0'}")
    tl, (al, kcl, kdl) = t.tolist(), (c.tolist() for c in cols)

    def swing(s: float) -> Command:
        return Command(*(float(np.interp(s, tl, c)) for c in (al, kcl, kdl)))

    return swing
