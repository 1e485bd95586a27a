"""SLIP parameters (report Table 1), validated on construction.

Units are SI throughout: kg, m, N/m, m/s^2. Stiffness ``k_c`` acts while the leg compresses
(q_rd <= 0), ``k_d`` after the bottom (q_rd > 0). ``g_s`` is the gravitational acceleration
during stance, ``g_f`` during flight (both positive numbers, pointing down). ``q_r_td`` and
``q_r_lo`` are the touchdown and liftoff leg lengths; both default to the rest length ``l0``
and must lie in (0, l0].
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

__all__ = ["SlipParams", "HUMAN_RUNNER", "ROBOT_HOPPER"]


@dataclass(frozen=True)
class SlipParams:
    """Physical parameters of the SLIP template (report Table 1)."""

    m: float = 80.0
    l0: float = 1.0
    k_c: float = 20_000.0
    k_d: float = 20_000.0
    g_s: float = 9.81
    g_f: float = 9.81
    q_r_td: float | None = None
    q_r_lo: float | None = None

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if value is None:
                continue
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise ValueError(f"SlipParams.{f.name} must be a real number, got {value!r}")
            if not math.isfinite(value) or value <= 0.0:
                raise ValueError(f"SlipParams.{f.name} must be finite and positive, got {value!r}")
            object.__setattr__(self, f.name, float(value))
        if self.q_r_td is None:
            object.__setattr__(self, "q_r_td", self.l0)
        if self.q_r_lo is None:
            object.__setattr__(self, "q_r_lo", self.l0)
        for name in ("q_r_td", "q_r_lo"):
            value = getattr(self, name)
            if value > self.l0:
                raise ValueError(
                    f"SlipParams.{name} must not exceed the rest length l0={self.l0!r}, got {value!r}"
                )

    @property
    def constant_stiffness(self) -> bool:
        """True when k_c == k_d (the setting of the report's section 3 maps)."""
        return self.k_c == self.k_d

    @property
    def k(self) -> float:
        """The single stiffness of a constant-stiffness leg; ValueError when k_c != k_d."""
        if not self.constant_stiffness:
            raise ValueError(
                f"this map assumes a constant leg stiffness (report section 3), got k_c={self.k_c!r} "
                f"!= k_d={self.k_d!r}"
            )
        return self.k_c

    def with_(self, **changes: float) -> SlipParams:
        """A copy with some fields changed (validated again)."""
        return replace(self, **changes)


#: The documented default case: an 80 kg human runner with a 1 m leg and a 20 kN/m spring.
HUMAN_RUNNER = SlipParams(m=80.0, l0=1.0, k_c=20_000.0, k_d=20_000.0, g_s=9.81, g_f=9.81)

#: A small robot hopper (about 3 kg, 0.25 m leg, 1.5 kN/m): dimensionless stiffness k l0/(m g) ~ 13,
#: softer than the human runner's ~ 25, so its sweep angles and compressions are larger.
ROBOT_HOPPER = SlipParams(m=3.0, l0=0.25, k_c=1_500.0, k_d=1_500.0, g_s=9.81, g_f=9.81)
