"""Report section 2.2 (SLIP dynamics): the unnumbered stance and flight displays, checked.

The report transcriptions here are typed as printed (errors included) and compared with the
derivations of :mod:`slipmaps.derive.model.mechanics`. The report's prose mentions coordinate
transfer maps between the Cartesian and polar states but prints none, so there is no row for them.
"""

from __future__ import annotations

import sympy as sp

from ..model import mechanics
from ..symbols import b_x, b_xd, b_y, b_yd, c, g_f, g_s, k, l0, m, q_r, q_rd, q_rdd, q_th, q_thd, q_thdd, t
from . import equation, expect_nonzero, expect_zero, forms


@equation(
    "sec2.2.1-polar",
    "polar stance dynamics (first display of 2.2.1)",
    "corrected",
    "Printed q_thdd = -g_s sin(q_th)/q_r - 2 q_r q_thd/q_r. The Euler-Lagrange equations of (1) give "
    "q_thdd = +g_s sin(q_th)/q_r - 2 q_rd q_thd/q_r: gravity tips the leg away from the vertical "
    "(as dp_th/dt = m g_s q_r sin q_th in (29)), and the Coriolis term has q_rd, not q_r. "
    "The q_rdd row is right.",
    derived=lambda: forms(*zip((q_rdd, q_thdd), mechanics.stance_polar_rhs()[1::2], strict=True)),
)
def check_stance_polar_display() -> None:
    """Printed: q_thdd = -g_s sin(q_th)/q_r - 2 q_r q_thd/q_r; q_rdd = F_s/m + q_r q_thd^2 - g_s cos q_th."""
    _, rdd, _, thdd = mechanics.stance_polar_rhs()
    printed_thdd = -g_s * sp.sin(q_th) / q_r - 2 * q_r * q_thd / q_r
    printed_rdd = k * (l0 - q_r) / m + q_r * q_thd**2 - g_s * sp.cos(q_th)
    corrected_thdd = g_s * sp.sin(q_th) / q_r - 2 * q_rd * q_thd / q_r
    expect_zero(printed_rdd - rdd, "sec2.2.1 printed q_rdd equals the Euler-Lagrange one")
    expect_nonzero(printed_thdd - thdd, "sec2.2.1 printed q_thdd differs from the Euler-Lagrange one")
    expect_zero(corrected_thdd - thdd, "sec2.2.1 corrected q_thdd equals the Euler-Lagrange one")


@equation(
    "sec2.2.1-damped",
    "polar stance dynamics with leg damping (not in the report)",
    "verified",
    "Not printed in the report: the leg damping extension, radial force -k (q_r - l0) - c q_rd "
    "(slipmaps' parameter c). From the Euler-Lagrange equations of (1) with the Rayleigh "
    "dissipation function R = c q_rd^2/2: q_rdd gains -c q_rd/m, q_thdd is unchanged (the damper "
    "acts along the leg, no torque about the toe); at c = 0 it is the row above.",
    derived=lambda: forms(*zip((q_rdd, q_thdd), mechanics.stance_polar_rhs(k, g_s, c)[1::2], strict=True)),
    extension=True,
)
def check_stance_polar_damped() -> None:
    """Printed: nothing (the report's leg is lossless); the stated extension, checked as if printed:
    m q_rdd = m q_r q_thd^2 + k (l0 - q_r) - c q_rd - m g_s cos q_th, the angular row of eq (3)
    unchanged."""
    el_r, el_th = mechanics.euler_lagrange_polar(k, g_s, c)
    _, el_th_lossless = mechanics.euler_lagrange_polar()
    stated = m * q_rdd - (m * q_r * q_thd**2 + k * (l0 - q_r) - c * q_rd - m * g_s * sp.cos(q_th))
    expect_zero(stated - el_r, "damped radial equation equals d/dt dL/dq_rd - dL/dq_r + dR/dq_rd")
    expect_zero(el_th - el_th_lossless, "damped angular equation equals the lossless one (eq 3)")
    _, rdd, _, thdd = mechanics.stance_polar_rhs(k, g_s, c)
    _, rdd_lossless, _, thdd_lossless = mechanics.stance_polar_rhs()
    expect_zero(rdd - rdd_lossless + c * q_rd / m, "damped q_rdd is the lossless one minus c q_rd/m")
    expect_zero(thdd - thdd_lossless, "damped q_thdd is the lossless one")
    damping = mechanics.stance_polar_damping()
    expect_zero(damping[1] + c * q_rd / m, "the damper's term of the field is -c q_rd/m on q_rdd")
    for i in (0, 2, 3):
        expect_zero(damping[i], f"the damper's term of the field is 0 on component {i}")


def _accelerations(rows):
    """d^2 b_x/dt^2 = rows[0], d^2 b_y/dt^2 = rows[1]."""
    return forms(*zip((sp.Derivative(b_x, (t, 2)), sp.Derivative(b_y, (t, 2))), rows, strict=True))


def _cartesian_rows(angle):
    """(b_xdd, b_ydd) = (-F_s sin(angle)/m, F_s cos(angle)/m - g_s), F_s = k (l0 - |b|) on flat ground."""
    force = k * (l0 - sp.sqrt(b_x**2 + b_y**2))
    return (-force * sp.sin(angle) / m, force * sp.cos(angle) / m - g_s)


@equation(
    "sec2.2.1-cartesian",
    "Cartesian stance dynamics, flat ground",
    "corrected",
    "b_xdd = -F_s sin(q_th)/m, b_ydd = F_s cos(q_th)/m - g_s hold, but the display substitutes "
    "q_th = arctan(b_y/b_x), the angle from the horizontal. With the Table 1 convention "
    "q_th = atan2(-b_x, b_y) (so sin q_th = -b_x/q_r, cos q_th = b_y/q_r). OCR noise in the "
    "square roots (b_y for b_y^2) ignored.",
    derived=lambda: _accelerations(_cartesian_rows(sp.atan2(-b_x, b_y))),
)
def check_stance_cartesian_display() -> None:
    """Printed (flat ground): b_xdd = -F_s sin(atan(b_y/b_x))/m, b_ydd = F_s cos(atan(b_y/b_x))/m - g_s."""
    _, xdd, _, ydd = mechanics.stance_cartesian_rhs()
    rows = _cartesian_rows
    # The first-line (polar) form b_xdd = -F sin(q_th)/m, b_ydd = F cos(q_th)/m - g_s holds with the
    # Table 1 angle; arctan(b_y / b_x), measured from the horizontal, is not q_th. The printed form
    # is refuted at one body position above the toe.
    point = {b_x: sp.Rational(-3, 10), b_y: sp.Rational(9, 10), b_xd: 2, b_yd: -1}
    printed, corrected = rows(sp.atan(b_y / b_x)), rows(sp.atan2(-b_x, b_y))
    for name, p, fixed, d in zip(("b_xdd", "b_ydd"), printed, corrected, (xdd, ydd), strict=True):
        expect_zero(
            fixed - d, f"sec2.2.1 {name} with q_th = atan2(-b_x, b_y) equals the Cartesian Lagrange one"
        )
        expect_nonzero(
            (p - d).subs(point), f"sec2.2.1 printed {name} (q_th = arctan(b_y/b_x)) differs at {point}"
        )


@equation(
    "sec2.2.2",
    "ballistic flight dynamics",
    "verified",
    "From L = m/2 (b_xd^2 + b_yd^2) - m g_f b_y; the toe state b_tx is bookkeeping.",
    derived=lambda: _accelerations(mechanics.flight_rhs()[1::2]),
)
def check_flight_display() -> None:
    """Printed: d/dt (b_x, b_xd, b_y, b_yd, b_tx) = (b_xd, 0, b_yd, -g_f, b_xd)."""
    printed = (b_xd, 0, b_yd, -g_f)
    names = ("d b_x", "d b_xd", "d b_y", "d b_yd")
    for name, p, d in zip(names, printed, mechanics.flight_rhs(), strict=True):
        expect_zero(p - d, f"sec2.2.2 printed {name}/dt equals the Lagrange one")
