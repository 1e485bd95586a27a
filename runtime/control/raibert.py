"""Raibert's hopping controller: the baseline every roboticist knows, as the runs' policy ``"raibert"``
on any plant (a map or the MuJoCo robot).

Raibert (1986, *Legged Robots That Balance*, ch. 2) split the control of a hopper into three parts
that ignore each other; two of them act on a planar SLIP:

* **speed by foot placement**: the foot lands ahead of the hip by the neutral point, half the
  distance the body travels in a stance, plus a correction proportional to the speed error,

      x_f = v T_s / 2 + k_v (v - v_d),      touchdown angle q_th = asin(x_f / q_r_td),

  ``v`` the measured apex speed, ``v_d`` the step's target speed, ``T_s`` the duration of the last
  stance the plant reported (before the first stance: the spring-mass half period
  pi sqrt(m / k_c)), ``k_v`` [s] the speed gain; the angle is set at the apex and held;
* **height by thrust**: here the leg's stiffness after the bottom, the thrust of a leg whose
  stiffness is set (report section 5: k_d > k_c adds (k_d - k_c)(l0 - q_r_b)^2 / 2 of energy),

      k_d = k_c (1 + k_0 + k_h (H - h) / l0 + k_i S),      S <- S + (H - h) / l0 after each step,

  ``h`` the measured apex height, ``H`` the target height, ``k_0`` the thrust at no height error
  (what makes up a hop's loss: 0 on the lossless SLIP), ``k_h`` the proportional and ``k_i`` the
  integral gain (dimensionless; the integral takes up what the thrust misses), k_c the nominal
  compression stiffness; k_d clipped into the scenario's k_d bounds (default [0.5, 2] k_c).

The third part, the body's attitude by hip torque in stance, is the robot's own
(``slipmaps.runtime.robot``, its ``pitch = "hinge"`` option).

Nothing here uses a map: the controller is the baseline a map-based controller is compared with.
Its gains (:class:`RaibertGains`) default to the ones a search on flat ground found best for the
MuJoCo robot (``slipmaps.runtime.studies.robot``: the search, its grid and its score are in
docs/robot.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

__all__ = ["RaibertGains", "RaibertState", "raibert_controls"]


@dataclass(frozen=True)
class RaibertGains:
    """The gains of Raibert's controller (module docstring): ``k_v`` [s] foot placement per unit of
    speed error, ``k_0`` (dimensionless) the thrust at no height error, ``k_h`` and ``k_i``
    (dimensionless) the height loop's proportional and integral gains on k_d / k_c."""

    k_v: float = 0.25
    k_0: float = 0.3
    k_h: float = 2.0
    k_i: float = 0.3

    def __post_init__(self):
        for f in fields(self):
            x = getattr(self, f.name)
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or x < 0:
                raise ValueError(f"RaibertGains.{f.name} must be a finite number >= 0, got {x!r}")
            object.__setattr__(self, f.name, float(x))


@dataclass
class RaibertState:
    """What Raibert's controller remembers between steps, per run: the last stance's duration
    ``t_stance`` [s] (NaN before the first) and the height loop's integral ``integral``."""

    t_stance: np.ndarray
    integral: np.ndarray

    @classmethod
    def of(cls, runs: int) -> RaibertState:
        return cls(np.full(runs, math.nan), np.zeros(runs))


def raibert_controls(gains: RaibertGains, params, h, v, H, V, t_stance, integral, k_d_bounds):
    """The touchdown angle and k_d of Raibert's controller (module docstring) for measured apexes
    ``h``, ``v`` and targets ``H``, ``V`` (arrays of rows), the rows' last stance durations
    ``t_stance`` (NaN: none yet) and height integrals ``integral``: ``(touchdown_angle, k_d)``."""
    T = np.where(np.isfinite(t_stance), t_stance, math.pi * math.sqrt(params.m / params.k_c))
    x_f = v * T / 2.0 + gains.k_v * (v - V)
    angle = np.arcsin(np.clip(x_f / params.q_r_td, -0.95, 0.95))
    k_d = params.k_c * (1.0 + gains.k_0 + gains.k_h * (H - h) / params.l0 + gains.k_i * integral)
    return angle, np.clip(k_d, *k_d_bounds)
