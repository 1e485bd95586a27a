"""The quantities by which two maps' steps are compared (one definition, for compare and accuracy).

Keys are result names of the map index (``t_stance``, ``bottom_q_r``, ..., ``apex_height`` for the
next apex). ``rel_scale`` names the scale of a relative error: ``self`` the reference value,
``compression`` the reference compression l0 - q_r_b (the leg length itself is always close to
l0), ``sweep`` the reference sweep |q_th - q_th_td| (both sides start from the same q_th_td).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Quantity", "QUANTITIES"]


@dataclass(frozen=True)
class Quantity:
    key: str
    label: str
    unit: str
    rel_scale: str


#: The compared quantities, in table order.
QUANTITIES: tuple[Quantity, ...] = (
    Quantity("t_stance", "stance time t_s", "s", "self"),
    Quantity("t_bottom", "bottom time t_b", "s", "self"),
    Quantity("bottom_q_r", "bottom leg length q_r_b", "m", "compression"),
    Quantity("bottom_q_th", "bottom leg angle q_th_b", "rad", "sweep"),
    Quantity("liftoff_q_rd", "liftoff leg rate q_rd_lo", "m/s", "self"),
    Quantity("liftoff_q_th", "liftoff leg angle q_th_lo", "rad", "sweep"),
    Quantity("liftoff_q_thd", "liftoff angle rate q_thd_lo", "rad/s", "self"),
    Quantity("apex_height", "next apex height", "m", "self"),
    Quantity("apex_speed", "next apex speed", "m/s", "self"),
)
