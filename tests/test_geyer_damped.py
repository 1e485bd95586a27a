"""Geyer et al.'s map with leg damping, ``geyer-damped`` (derive/maps/geyer_damped.py, on the
radial solution of derive/maps/geyer_damped_helpers.py, registry entries sec3.1-damped*), against
its own derivation and against the exact damped map.

The derivation's closed forms (rho(t), rho'(t), the leg angle and the bottom time) are lambdified
here, liftoff (option ``force``: the leg force k (l0 - q_r) - c q_rd falls to 0, or q_r = q_r_lo if
first) is the root of the derived force between the bottom and half a damped period later by
``brentq``, and the exact flights (closed form) take the body from the apex to touchdown and from
liftoff to the next apex: an evaluation of the derivation independent of the generated kernels (the
IR, the code generator, the safeguarded Halley iteration of the map's liftoff). The ground truth is
``slipmaps.apex_return("exact", ...)`` with the same c.
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


def damped_geyer_liftoff(p: SlipParams, height: float, speed: float, angle: float) -> tuple[float, ...]:
    """Liftoff time after touchdown and polar liftoff state of the damped closed forms (flat ground,
    touchdown at q_r = l0 after the exact descent from the apex), liftoff by ``brentq``."""
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
    rho_lo = p.q_r_lo / p.l0 - 1.0

    def g(s):  # below 0 until liftoff: the leg force is positive and q_r below q_r_lo
        return max(-_FORCE(s, *args), _RHO(s, *args) - rho_lo)

    # the first sign change on a fine grid after the bottom, then brentq in its cell
    grid = np.linspace(t_b, t_end, 2001)
    first = next(i for i, s in enumerate(grid) if g(s) >= 0.0)
    t_lo = brentq(g, grid[first - 1], grid[first], xtol=1e-16)
    rho = _RHO(t_lo, *args)
    return (
        t_lo,
        p.l0 * (1.0 + rho),
        p.l0 * _RATE(t_lo, *args),
        angle + _ANGLE(t_lo, *args),
        w / (1.0 + rho) ** 2,
    )


def damped_geyer_apex(p: SlipParams, height: float, speed: float, angle: float) -> tuple[float, float]:
    """Next apex (height, speed) of the damped closed forms, flat ground, touchdown at q_r = l0."""
    _, q_r, q_rd, q_th, q_thd = damped_geyer_liftoff(p, height, speed, angle)
    x_d = -q_rd * math.sin(q_th) - q_r * math.cos(q_th) * q_thd
    y_d = q_rd * math.cos(q_th) - q_r * math.sin(q_th) * q_thd
    return q_r * math.cos(q_th) + max(y_d, 0.0) ** 2 / (2.0 * p.g_f), x_d


def _apex(name: str, p: SlipParams, height: float, speed: float, angle: float, **options):
    res = slipmaps.apex_return(
        name, p, apex_height=height, apex_speed=speed, touchdown_angle=angle, **options
    )
    assert res.status == Status.OK, (name, res.message, height, speed, angle, options)
    return res.values["next_apex_height"], res.values["next_apex_speed"]


def _ratio(zeta: float) -> SlipParams:
    """The human runner with the damping ratio c / (2 sqrt(k m)) = ``zeta``."""
    return HUMAN_RUNNER.with_(c=zeta * 2.0 * math.sqrt(HUMAN_RUNNER.k * HUMAN_RUNNER.m))


@pytest.mark.parametrize("zeta", [0.0, 0.05, 0.2])
def test_geyer_damped_map_is_its_derivation(zeta):
    """The generated map's next apex equals the lambdified closed forms (measured at most 5.7e-14 m,
    m/s over the 45 steps at ratios 0-0.2)."""
    p = _ratio(zeta)
    for step in STEPS:
        got = _apex("geyer-damped", p, *step)
        want = damped_geyer_apex(p, *step)
        assert abs(got[0] - want[0]) < 1e-12 and abs(got[1] - want[1]) < 1e-12, (step, got, want)


#: Shallow steps (apex 2-20 mm above the touchdown height, touchdown angles 0.10-0.14 rad, 5-6 m/s)
#: for a liftoff leg length below l0: there the leg can reach q_r_lo before its force falls to 0.
SHALLOW = tuple(
    (math.cos(angle) + rise, speed, angle)
    for angle in (0.10, 0.12, 0.14)
    for speed in (5.0, 6.0)
    for rise in (0.002, 0.005, 0.02)
)


@pytest.mark.parametrize(
    ("zeta", "q_r_lo", "steps", "bound"),
    [
        (0.0, 1.0, STEPS, 4e-15),
        (0.05, 1.0, STEPS, 4e-15),
        (0.1, 1.0, STEPS, 4e-15),
        (0.2, 1.0, STEPS, 4e-15),
        (0.2, 0.99, SHALLOW, 5e-14),
    ],
    ids=["0", "0.05", "0.1", "0.2", "0.2-short-liftoff-leg"],
)
def test_geyer_damped_liftoff_time_is_the_roots(zeta, q_r_lo, steps, bound):
    """The kernel's liftoff (safeguarded Halley from the frozen-decay root, Taylor steps near it)
    lands on the derivation's first root, found on a fine grid and by ``brentq`` (xtol 1e-16):
    stance times equal to a relative 1.4e-15 at most over the 45 steps (measured). On the shallow
    steps with q_r_lo = 0.99 m, q_r = q_r_lo comes first on some (the leg force's zero on the
    others); where it does, q_r_lo lies just below the highest leg length of the damped oscillation
    and the root is ill-conditioned (measured 2.4e-14)."""
    p = _ratio(zeta).with_(q_r_lo=q_r_lo)
    by_length = 0
    for step in steps:
        want = damped_geyer_liftoff(p, *step)[0]
        res = slipmaps.stance("geyer-damped", p, _touchdown(p, *step))
        assert res.ok, (step, res.message)
        got = res["t_stance"]
        assert abs(got - want) <= bound * want, (step, got, want)
        by_length += res["liftoff_q_r"] == q_r_lo
    if q_r_lo < p.l0:  # both conditions decide some steps (measured: q_r_lo 2 of the 18)
        assert 0 < by_length < len(steps), by_length


def test_geyer_damped_at_c0_is_geyers_map():
    """At c = 0 the damped map is Geyer et al.'s (11), (19), (17) split at the bottom: the ``geyer``
    map's next apex to round-off (measured 3.0e-14 m, m/s), not bit for bit (other closed forms)."""
    p = HUMAN_RUNNER.with_(c=0.0)
    for step in STEPS:
        got, want = _apex("geyer-damped", p, *step), _apex("geyer", p, *step)
        assert abs(got[0] - want[0]) < 1e-12 and abs(got[1] - want[1]) < 1e-12, (step, got, want)


def next_apex_errors(p: SlipParams, **options) -> np.ndarray:
    """Relative next-apex errors of ``geyer-damped`` (the larger of height and speed) over :data:`STEPS`."""
    errors = []
    for step in STEPS:
        ref_h, ref_v = _apex("exact", p, *step)
        got_h, got_v = _apex("geyer-damped", p, *step, **options)
        errors.append(max(abs(got_h - ref_h) / ref_h, abs(got_v - ref_v) / abs(ref_v)))
    return np.array(errors)


#: (gravity option, damping ratio c / (2 sqrt(k m))) -> (measured mean, measured max) relative
#: next-apex error over STEPS (45 steps); the bound asserted is the measurement plus a fifth, and the
#: issue's target (5 %) for the map without a correction.
MEASURED = {
    ("none", 0.0): (0.0097, 0.0313),
    ("none", 0.02): (0.0088, 0.0251),
    ("none", 0.05): (0.0092, 0.0290),
    ("none", 0.1): (0.0137, 0.0364),
    ("none", 0.2): (0.0244, 0.0478),
    ("type0", 0.0): (0.0143, 0.0507),
    ("type0", 0.02): (0.0123, 0.0440),
    ("type0", 0.05): (0.0098, 0.0356),
    ("type0", 0.1): (0.0068, 0.0249),
    ("type0", 0.2): (0.0038, 0.0117),
    ("type1", 0.0): (0.0132, 0.0478),
    ("type1", 0.02): (0.0112, 0.0413),
    ("type1", 0.05): (0.0088, 0.0331),
    ("type1", 0.1): (0.0058, 0.0228),
    ("type1", 0.2): (0.0026, 0.0103),
    ("type2", 0.0): (0.0129, 0.0470),
    ("type2", 0.02): (0.0109, 0.0405),
    ("type2", 0.05): (0.0085, 0.0323),
    ("type2", 0.1): (0.0055, 0.0220),
    ("type2", 0.2): (0.0025, 0.0097),
    ("type3", 0.0): (0.0141, 0.0498),
    ("type3", 0.02): (0.0121, 0.0432),
    ("type3", 0.05): (0.0096, 0.0349),
    ("type3", 0.1): (0.0066, 0.0242),
    ("type3", 0.2): (0.0033, 0.0112),
    ("type4", 0.0): (0.0129, 0.0470),
    ("type4", 0.02): (0.0110, 0.0406),
    ("type4", 0.05): (0.0086, 0.0325),
    ("type4", 0.1): (0.0056, 0.0223),
    ("type4", 0.2): (0.0025, 0.0100),
}


@pytest.mark.parametrize(("gravity", "zeta"), sorted(MEASURED), ids=lambda x: str(x))
def test_geyer_damped_accuracy_against_exact_damped_map(gravity, zeta):
    errors = next_apex_errors(_ratio(zeta), gravity=gravity)
    assert len(errors) == len(STEPS) == 45
    mean, worst = MEASURED[(gravity, zeta)]
    assert errors.mean() <= 1.2 * mean, errors.mean()
    assert errors.max() <= (min(1.2 * worst, 0.05) if gravity == "none" else 1.2 * worst), errors.max()


def _touchdown(p: SlipParams, height: float, speed: float, angle: float) -> tuple[float, ...]:
    """The polar touchdown state at q_r = l0 after the exact descent from the apex (as
    :func:`damped_geyer_apex`)."""
    b_y, b_x = p.l0 * math.cos(angle), -p.l0 * math.sin(angle)
    b_yd = -math.sqrt(2.0 * p.g_f * (height - b_y))
    return (p.l0, (b_x * speed + b_y * b_yd) / p.l0, angle, (b_x * b_yd - speed * b_y) / p.l0**2)


#: Gauss-Legendre nodes and weights on [-1, 1] for a half's average leg length (the damped rho(t) is
#: smooth on each half: 32 nodes integrate it to rounding).
_GL = np.polynomial.legendre.leggauss(32)


def _mean_leg_length(p: SlipParams, touchdown, t_from: float, t_to: float, gravity: str) -> float:
    """The mean of the map's own q_r(t) (``slipmaps.trajectory``) on [t_from, t_to], by quadrature."""
    nodes, weights = _GL
    times = t_from + (nodes + 1.0) * (t_to - t_from) / 2.0
    _, states, status = slipmaps.trajectory("geyer-damped", p, touchdown, times, gravity=gravity)
    assert status == Status.OK
    return float(weights @ states[:, 0]) / 2.0


@pytest.mark.parametrize("gravity", ["type0", "type1", "type2", "type3", "type4"])
def test_eq48_each_half_impulse_at_the_types_leg_length(gravity):
    """The fixed point's virtual gravity effect of each half is (48) on that half from the torque
    m g_s q_r sin q_th at its two ends, with the type's leg length: l0 (type 0, as (49)),
    (l0 + q_r_b)/2 (type 1, (52)), the stance mean of q_r (type 2, (62)), the true ones (type 3,
    (65)), each half's mean (type 4, (76)); recomputed here from the map's own event states and
    trajectory (measured at most 4e-14 of the momentum scale m l0 sqrt(g_s l0) over 15 steps at 10 %
    of the critical damping; the fixed point stops within 1e-12 of its scale)."""
    p = _ratio(0.1)
    steps = [s for s in STEPS if s[0] == 1.05]
    assert len(steps) == 15
    for height, speed, angle in steps:
        touchdown = _touchdown(p, height, speed, angle)
        res = slipmaps.stance("geyer-damped", p, touchdown, gravity=gravity)
        assert res.ok, res.message
        t_b, t_s, q_r_b = res["t_bottom"], res["t_stance"], res["bottom_q_r"]
        means = [_mean_leg_length(p, touchdown, lo, hi, gravity) for lo, hi in ((0.0, t_b), (t_b, t_s))]
        stance_mean = (t_b * means[0] + (t_s - t_b) * means[1]) / t_s
        lengths = {
            "type0": (p.l0,) * 4,
            "type1": ((p.l0 + q_r_b) / 2.0,) * 4,
            "type2": (stance_mean,) * 4,
            "type3": (p.l0, q_r_b, q_r_b, res["liftoff_q_r"]),
            "type4": (means[0], means[0], means[1], means[1]),
        }[gravity]
        # each half's two ends: touchdown and bottom, bottom and liftoff
        angles = (angle, res["bottom_q_th"], res["bottom_q_th"], res["liftoff_q_th"])
        torque = [p.m * p.g_s * r * math.sin(th) for r, th in zip(lengths, angles, strict=True)]
        want = (t_b * (torque[0] + torque[1]) / 2.0, (t_s - t_b) * (torque[2] + torque[3]) / 2.0)
        got = (res["P_c_compression"], res["P_c_decompression"])
        scale = p.m * p.l0 * math.sqrt(p.g_s * p.l0)
        assert abs(got[0] - want[0]) < 1e-11 * scale and abs(got[1] - want[1]) < 1e-11 * scale, (got, want)
        assert min(abs(got[0]), abs(got[1])) > 1e-3 * scale  # the correction is not empty


def test_force_liftoff_is_the_leg_forces_zero():
    """With ``liftoff="force"`` the leg lifts off where k_d (l0 - q_r) - c q_rd = 0, before q_r = l0
    (measured at most 2.3e-10 N over the 15 steps at 1 m apex height, 10 % critical); with
    ``"length"`` at q_r = q_r_lo exactly."""
    p = _ratio(0.1)
    steps = [s for s in STEPS if s[0] == 1.0]
    assert len(steps) == 15
    for height, speed, angle in steps:
        touchdown = _touchdown(p, height, speed, angle)
        force = slipmaps.stance("geyer-damped", p, touchdown)
        length = slipmaps.stance("geyer-damped", p, touchdown, liftoff="length")
        leg = p.k_d * (p.l0 - force["liftoff_q_r"]) - p.c * force["liftoff_q_rd"]
        assert abs(leg) < 1e-8, leg
        assert force["liftoff_q_r"] < p.l0 and force["t_stance"] < length["t_stance"]
        assert length["liftoff_q_r"] == p.q_r_lo


def test_overdamped_leg_is_its_own_status():
    """A leg damped beyond the approximate oscillator's critical damping (delta >= omega_n) has no
    damped oscillation: status OVERDAMPED, outputs NaN, one line naming it."""
    res = slipmaps.apex_return("geyer-damped", _ratio(1.5), 1.0, 5.0, 0.4)
    assert res.status == Status.OVERDAMPED and not res.ok
    assert math.isnan(res.values["next_apex_height"])
    assert "critical damping" in res.message


def test_deadbeat_finds_a_damped_gait_with_geyer_damped():
    """The deadbeat step on geyer-damped finds the k_d that puts back what the damper takes (10 %
    critical: measured 35.4 kN/m at 0.355 rad against the exact map's 37.3 kN/m at 0.347 rad), and the
    exact map, run with that plan, keeps the speed within 1 % (measured 0.3 %)."""
    p = HUMAN_RUNNER.with_(c=253.0)
    plan = slipmaps.deadbeat("geyer-damped", p, 1.0, 5.0, 1.0, 5.0, controls=("touchdown_angle", "k_d"))
    assert plan.status.name == "REACHED", plan.message
    assert plan.k_d > 1.6 * p.k_c
    exact = slipmaps.deadbeat("exact", p, 1.0, 5.0, 1.0, 5.0, controls=("touchdown_angle", "k_d"))
    assert abs(plan.k_d / exact.k_d - 1.0) < 0.06 and abs(plan.touchdown_angle - exact.touchdown_angle) < 0.01
    step = slipmaps.apex_return(
        "exact", p.with_(k_d=plan.k_d), apex_height=1.0, apex_speed=5.0, touchdown_angle=plan.touchdown_angle
    )
    assert abs(step.values["next_apex_speed"] / 5.0 - 1.0) < 0.01, step.values
