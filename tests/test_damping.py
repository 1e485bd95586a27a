"""The leg damping ``c`` (derive/params.py): the exact map's damped stance (generated/exact_stance.py)
against an independent integration, its two liftoff conventions, the energy it dissipates, its
Jacobian, and the maps that refuse it.

The damped stance (derive/model/mechanics.py, registry entry sec2.2.1-damped): the radial force is
-k (q_r - l0) - c q_rd, k = k_c until the bottom (q_rd = 0) and k_d after it; with
``liftoff="force"`` (default) the stance ends where the leg force k_d (l0 - q_r) - c q_rd falls to 0
(the ground cannot pull) or at q_r = q_r_lo, whichever comes first; with ``liftoff="length"`` at
q_r = q_r_lo. The reference here is written out on its own (its right-hand side, its events) and
integrated by scipy's solve_ivp (DOP853, rtol 1e-12), carrying the dissipated energy
W = integral of c q_rd^2 dt as a fifth component.
"""

from __future__ import annotations

import math

import pytest
import slipmaps
from scipy.integrate import solve_ivp
from slipmaps.generated import exact_stance as ej
from slipmaps.generated.status import Status
from slipmaps.runtime.api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams

NAMES = ej.STANCE_NAMES


def critical(p: SlipParams) -> float:
    """The leg's critical damping 2 sqrt(k_c m) [N s/m]."""
    return 2.0 * math.sqrt(p.k_c * p.m)


def _field(p: SlipParams, k: float):
    def rhs(_t, y):
        q_r, q_rd, q_th, q_thd, _ = y
        force = k * (p.l0 - q_r) - p.c * q_rd
        q_rdd = q_r * q_thd**2 - p.g_s * math.cos(q_th) + force / p.m
        q_thdd = p.g_s * math.sin(q_th) / q_r - 2.0 * q_rd * q_thd / q_r
        return [q_rd, q_rdd, q_thd, q_thdd, p.c * q_rd**2]

    return rhs


def _event(fun, direction):
    def event(t, y):
        return fun(y)

    event.terminal, event.direction = True, direction
    return event


def reference(p: SlipParams, touchdown, liftoff: str = "force") -> tuple[dict, float]:
    """The damped stance by solve_ivp (module docstring): (its stance row by name, the energy the
    damper dissipated [J])."""
    tol = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-13, "dense_output": False}
    bottom = solve_ivp(
        _field(p, p.k_c), (0.0, 10.0), [*touchdown, 0.0], events=_event(lambda y: y[1], 1.0), **tol
    )
    assert bottom.status == 1 and len(bottom.t_events[0]) == 1
    t_b, y_b = bottom.t_events[0][0], bottom.y_events[0][0].copy()
    y_b[1] = 0.0
    events = [_event(lambda y: y[0] - p.q_r_lo, 1.0)]
    if liftoff == "force":
        events.append(_event(lambda y: p.k_d * (p.l0 - y[0]) - p.c * y[1], -1.0))
    lift = solve_ivp(_field(p, p.k_d), (t_b, t_b + 10.0), y_b, events=events, **tol)
    assert lift.status == 1
    hit = [(e[0], y[0]) for e, y in zip(lift.t_events, lift.y_events, strict=True) if len(e)]
    t_lo, y_lo = min(hit, key=lambda h: h[0])
    row = {"t_bottom": t_b, "t_stance": t_lo}
    for j, q in enumerate(("q_r", "q_rd", "q_th", "q_thd")):
        row[f"bottom_{q}"], row[f"liftoff_{q}"] = y_b[j], y_lo[j]
    return row, y_lo[4]


def energy(p: SlipParams, k: float, state) -> float:
    """The stance energy of a polar state with stiffness k (kinetic + spring + gravity above the toe)."""
    q_r, q_rd, q_th, q_thd = state
    return (
        0.5 * p.m * (q_rd**2 + (q_r * q_thd) ** 2)
        + 0.5 * k * (p.l0 - q_r) ** 2
        + p.m * p.g_s * q_r * math.cos(q_th)
    )


TOUCHDOWN = (1.0, -1.2, 0.35, -4.6)
ROBOT_TOUCHDOWN = (0.25, -0.5, 0.3, -6.0)
#: (params, touchdown, liftoff): light to strong damping (fractions of critical), k_c != k_d, a
#: liftoff length below l0, both conventions.
CASES = [
    pytest.param(HUMAN_RUNNER.with_(c=0.02 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-2%"),
    pytest.param(HUMAN_RUNNER.with_(c=0.1 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-10%"),
    pytest.param(HUMAN_RUNNER.with_(c=0.2 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-20%"),
    pytest.param(
        HUMAN_RUNNER.with_(c=0.1 * critical(HUMAN_RUNNER)), TOUCHDOWN, "length", id="human-10%-length"
    ),
    pytest.param(
        HUMAN_RUNNER.with_(k_d=24_000.0, c=0.1 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-kd24k"
    ),
    pytest.param(
        HUMAN_RUNNER.with_(q_r_lo=0.97, c=0.05 * critical(HUMAN_RUNNER)), TOUCHDOWN, "force", id="human-qrlo"
    ),
    pytest.param(
        ROBOT_HOPPER.with_(c=0.1 * critical(ROBOT_HOPPER)), ROBOT_TOUCHDOWN, "force", id="robot-10%"
    ),
]


@pytest.mark.parametrize(("params", "touchdown", "liftoff"), CASES)
def test_damped_stance_matches_an_independent_integration(params, touchdown, liftoff):
    got = slipmaps.stance("exact", params, touchdown, liftoff=liftoff)
    assert got.status == Status.OK
    ref, _ = reference(params, touchdown, liftoff)
    worst = max(abs(got.values[n] - ref[n]) for n in NAMES)
    # Measured over CASES: at most MEASURED (SI units: s, m, m/s, rad, rad/s).
    assert worst < 1e-9, worst
