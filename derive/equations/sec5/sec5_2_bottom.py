"""The end of report section 5.2 (rows 152-154): the bottom leg length q_r_b, checked against the
energy (27) at a vertical bottom (:func:`~slipmaps.derive.maps.geyer_vs.bottom_quartic`) and
Geyer's bottom (13) with the parameters of section 5.1.1. Row 152 carries no tag in the scan; its
note says how the number was assigned.
"""

from __future__ import annotations

import sympy as sp

from ...maps import geyer, geyer_vs
from ...maps.iterative_helpers import E_ab
from ...model import mechanics
from ...symbols import E, g_s, k_c, l0, m, p_th, q_r, q_rd, q_th, q_thd, t
from .. import equation, expect_nonzero, expect_zero
from .helpers import KG, METRE, SECOND
from .sec5_1 import AB, a_ab, b_ab, derived_radius, printed_eq81

# --------------------------------------------------------------------------------------------
# End of section 5.2: the bottom leg length q_r_b, (152)-(154).


def _vertical_bottom_energy():
    """The total energy (27) with k_c at a vertical bottom: q_rd = 0, q_th = 0, q_thd = p_th/(m q_r^2)."""
    return mechanics.stance_energy(k_c).subs({q_rd: 0, q_th: 0, q_thd: p_th / (m * q_r**2)})


@equation(
    "152",
    "E_ab at a vertical bottom",
    "corrected",
    "Number assumed: the scan tags only the second line of the two-line display (153); its first line "
    "is taken as (152). It prints p_th/(2 m q_r^2) for the rotational energy, which is "
    "p_th^2/(2 m q_r^2) (the printed term is in 1/s, not J). Corrected: E_ab = p_th^2/(2 m q_r^2) + "
    "k_c/2 (l0 - q_r)^2 + m g_s q_r, the energy (27) with k_c at q_rd = 0, q_th = 0; (153) is q_r^2 "
    "times the corrected form.",
)
def check_eq152() -> None:
    """Printed: E_ab = p_th/(2 m q_r^2) + k_c/2 (l0 - q_r)^2 + m g_s q_r."""
    printed = p_th / (2 * m * q_r**2) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    corrected = p_th**2 / (2 * m * q_r**2) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    derived = _vertical_bottom_energy()
    expect_nonzero(printed - derived, "eq 152 printed E_ab differs from (27) at a vertical bottom")
    expect_zero(corrected - derived, "eq 152 corrected E_ab equals (27) with k_c at a vertical bottom")
    kg, metre, second = KG, METRE, SECOND
    scale = {m: m * kg, q_r: q_r * metre, p_th: p_th * kg * metre**2 / second}
    rotational = p_th / (2 * m * q_r**2)
    expect_zero(
        sp.simplify(rotational.subs(scale, simultaneous=True) / rotational) - 1 / second,
        "eq 152 the printed rotational term is in 1/s",
    )
    expect_zero(
        (q_r**2 * (corrected - E)).expand() - geyer_vs.bottom_quartic(),
        "eq 152 (153)'s quartic is q_r^2 times the corrected form minus E",
    )


@equation(
    "153",
    "bottom quartic in q_r",
    "verified",
    "q_r^2 (E - E_ab) with E the energy (27) with k_c at a vertical bottom (geyer_vs.bottom_quartic); "
    "follows from the corrected (152), not the printed one.",
)
def check_eq153() -> None:
    """Printed: k_c/2 q_r^4 + (m g_s - k_c l0) q_r^3 + (k_c l0^2/2 - E_ab) q_r^2 + p_th^2/(2 m) = 0."""
    printed = (
        k_c / 2 * q_r**4
        + (m * g_s - k_c * l0) * q_r**3
        + (k_c * l0**2 / 2 - E_ab) * q_r**2
        + p_th**2 / (2 * m)
    )
    expect_zero(
        printed - geyer_vs.bottom_quartic().subs(E, E_ab), "eq 153 printed quartic equals q_r^2 (E - E_ab)"
    )
    printed152 = p_th / (2 * m * q_r**2) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    expect_nonzero(
        printed - sp.expand(q_r**2 * (printed152 - E_ab)), "eq 153 does not follow from (152) as printed"
    )


@equation(
    "154",
    "q_r_b = l0 (1 + a_ab - b_ab)",
    "verified",
    "Geyer's bottom: (78) at the bottom phase (81), 3 pi/2 + 2 n pi, with a_ab, b_ab of section 5.1.1.",
)
def check_eq154() -> None:
    """Printed: q_r_b = l0 (1 + a_ab - b_ab)."""
    printed = l0 * (1 + a_ab - b_ab)
    expect_zero(printed - derived_radius(AB).subs(t, printed_eq81()), "eq 154 printed q_r_b is (78) at (81)")
    bottom = geyer.event_states()["bottom"][0].subs(AB.names)
    expect_zero(printed - bottom, "eq 154 printed q_r_b is Geyer's bottom state (13) with the ab parameters")
