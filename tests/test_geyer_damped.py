"""Geyer et al.'s radial solution with leg damping (derive/maps/geyer_damped_helpers.py, registry
entries sec3.1-damped*), evaluated from its SymPy closed forms against the exact damped map.

No generated map evaluates it yet: here the derivation's rho(t), rho'(t), leg angle and bottom time
are lambdified, liftoff (option ``force``: the leg force k (l0 - q_r) - c q_rd falls to 0, or
q_r = q_r_lo if first) is the root of the derived force between the bottom and half a damped period
later, and the exact flights (closed form) take the body from the apex to touchdown and from
liftoff to the next apex. The ground truth is ``slipmaps.apex_return("exact", ...)`` with the same c.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
import sympy as sp
from scipy.optimize import brentq
from slipmaps.derive.maps import geyer_damped_helpers as h
from slipmaps.derive.symbols import a, g_s, l0, omega, omega0, t
from slipmaps.generated.status import Status
from slipmaps.runtime.api.params import HUMAN_RUNNER, SlipParams

_ARGS = (t, h.RHO_TD, h.RHO_D_TD, omega, omega0, h.DELTA, h.OMEGA_D, l0, g_s)


def _lambdify(expr):
    _, coeffs = h.damped_radial_solution()
    full = expr.subs({h.A_C: coeffs[h.A_C], h.B_S: coeffs[h.B_S]}).subs(a, coeffs[a])
    return sp.lambdify(_ARGS, full, "math")


_RHO = _lambdify(h.damped_radial_solution()[0])
_RATE = _lambdify(h.damped_events()["rate"])
_FORCE = _lambdify(h.damped_events()["force"])
_BOTTOM = _lambdify(h.damped_events()["t_bottom"])
_ANGLE = _lambdify(h.damped_leg_angle())

#: Touchdown angles near the exact map's periodic ones at c = 0 for the human runner, per apex height
#: and speed (brentq over the angle on the exact next apex height; measured once, in degrees).
PERIODIC_DEG = {
    1.0: (17.22, 20.57, 23.56, 26.3, 28.87),
    1.05: (17.03, 20.75, 24.0, 26.93, 29.65),
    1.1: (16.89, 20.83, 24.26, 27.34, 30.18),
}
SPEEDS = (3.0, 4.0, 5.0, 6.0, 7.0)
#: The accuracy steps: every apex height and speed, at the periodic angle and 0.02 rad either side.
STEPS = tuple(
    (height, speed, math.radians(deg) + d)
    for height, angles in PERIODIC_DEG.items()
    for speed, deg in zip(SPEEDS, angles, strict=True)
    for d in (-0.02, 0.0, 0.02)
)


def damped_geyer_apex(p: SlipParams, height: float, speed: float, angle: float) -> tuple[float, float]:
    """Next apex (height, speed) of the damped closed forms, flat ground, touchdown at q_r = l0."""
    b_y, b_x = p.l0 * math.cos(angle), -p.l0 * math.sin(angle)
    b_yd, b_xd = -math.sqrt(2.0 * p.g_f * (height - b_y)), speed
    q_rd = (b_x * b_xd + b_y * b_yd) / p.l0
    w = (b_x * b_yd - b_xd * b_y) / p.l0**2  # q_thd at touchdown = omega at q_r = l0
    w0 = math.sqrt(p.k / p.m)
    delta = p.c / (2.0 * p.m)
    w_d = math.sqrt(w0**2 + 3.0 * w**2 - delta**2)
    args = (0.0, q_rd / p.l0, w, w0, delta, w_d, p.l0, p.g_s)
    t_b = _BOTTOM(0.0, *args)
    t_end = t_b + math.pi / w_d
    t_lo = brentq(lambda s: _FORCE(s, *args), t_b, t_end, xtol=1e-15)
    rho_lo = p.q_r_lo / p.l0 - 1.0
    if _RHO(t_end, *args) > rho_lo:
        t_lo = min(t_lo, brentq(lambda s: _RHO(s, *args) - rho_lo, t_b, t_end, xtol=1e-15))
    rho = _RHO(t_lo, *args)
    q_r, q_rd, q_th = p.l0 * (1.0 + rho), p.l0 * _RATE(t_lo, *args), angle + _ANGLE(t_lo, *args)
    q_thd = w / (1.0 + rho) ** 2
    x_d = -q_rd * math.sin(q_th) - q_r * math.cos(q_th) * q_thd
    y_d = q_rd * math.cos(q_th) - q_r * math.sin(q_th) * q_thd
    return q_r * math.cos(q_th) + max(y_d, 0.0) ** 2 / (2.0 * p.g_f), x_d


def next_apex_errors(p: SlipParams) -> np.ndarray:
    """Relative next-apex errors (the larger of height and speed) over :data:`STEPS`."""
    errors = []
    for height, speed, angle in STEPS:
        ref = slipmaps.apex_return("exact", p, apex_height=height, apex_speed=speed, touchdown_angle=angle)
        assert ref.status == Status.OK, (height, speed, angle)
        got_h, got_v = damped_geyer_apex(p, height, speed, angle)
        errors.append(
            max(
                abs(got_h - ref.values["next_apex_height"]) / ref.values["next_apex_height"],
                abs(got_v - ref.values["next_apex_speed"]) / abs(ref.values["next_apex_speed"]),
            )
        )
    return np.array(errors)


def test_damped_solution_at_c0_is_geyers_map():
    """At c = 0 the damped closed forms are Geyer et al.'s (11), (19), (17): the generated map's next
    apex to round-off (measured 1.2e-14 m, m/s)."""
    p = HUMAN_RUNNER.with_(c=0.0)
    for height, speed, angle in STEPS:
        res = slipmaps.apex_return("geyer", p, apex_height=height, apex_speed=speed, touchdown_angle=angle)
        assert res.status == Status.OK
        got_h, got_v = damped_geyer_apex(p, height, speed, angle)
        assert abs(got_h - res.values["next_apex_height"]) < 1e-12
        assert abs(got_v - res.values["next_apex_speed"]) < 1e-12


#: Damping ratio c / (2 sqrt(k m)) -> (measured mean, measured max) relative next-apex error over
#: STEPS (45 steps), the bound asserted being the max plus a fifth: the issue's target is 5 %.
MEASURED = {0.02: (0.0088, 0.0251), 0.05: (0.0092, 0.0290), 0.1: (0.0137, 0.0364), 0.2: (0.0244, 0.0478)}


@pytest.mark.parametrize("ratio", sorted(MEASURED))
def test_damped_geyer_accuracy_against_exact_damped_map(ratio):
    p = HUMAN_RUNNER.with_(c=ratio * 2.0 * math.sqrt(HUMAN_RUNNER.k * HUMAN_RUNNER.m))
    errors = next_apex_errors(p)
    assert len(errors) == len(STEPS) == 45
    mean, worst = MEASURED[ratio]
    assert errors.mean() <= 1.2 * mean, errors.mean()
    assert errors.max() <= min(1.2 * worst, 0.05), errors.max()
