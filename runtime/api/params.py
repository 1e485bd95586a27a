"""SLIP parameters (report Table 1), validated on construction.

Units are SI throughout: kg, m, N/m, m/s^2. ``SlipParams(m=80, l0=1, k=20_000)`` gives a leg of
constant stiffness ``k``; ``k_c`` / ``k_d`` set the stiffness while the leg compresses (until the
bottom) and after the bottom separately (report section 5). ``g_s`` is the gravitational
acceleration during stance, ``g_f`` during flight (both positive numbers, pointing down).
``q_r_td`` and ``q_r_lo`` are the touchdown and liftoff leg lengths; both default to the rest
length ``l0`` and must lie in (0, l0]. Every field defaults to the human runner
(:data:`HUMAN_RUNNER`: 80 kg, 1 m leg, 20 kN/m). A value that is not a real number (a string, say)
is a TypeError (:class:`ParamTypeError`, also a ValueError), one out of its domain a ValueError
(:class:`ParamError`);
both name the argument given (``k`` when ``k`` set both stiffnesses).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

from .numeric import NotANumber, is_real, num

__all__ = ["SlipParams", "ParamError", "ParamTypeError", "HUMAN_RUNNER", "ROBOT_HOPPER"]

_DEFAULT_K = 20_000.0


class _ParamProblem:
    """A bad parameter: ``field`` is the argument's name (``k`` when ``k`` set ``k_c`` and ``k_d``),
    ``problem`` what is wrong, ``value`` the value given; the command line names its flag from them."""

    def __init__(self, field: str, problem: str, value: object) -> None:
        self.field, self.problem, self.value = field, problem, value
        super().__init__(f"SlipParams.{field} {problem}, got {num(value)}")


class ParamError(_ParamProblem, ValueError):
    """A parameter out of its domain (not finite, not positive, a leg length above l0)."""


class ParamTypeError(_ParamProblem, NotANumber):
    """A parameter that is not a real number (a string, bytes, None, a bool): a TypeError (and a
    ValueError, see :class:`~.numeric.NotANumber`)."""


@dataclass(frozen=True, init=False)
class SlipParams:
    """Physical parameters of the SLIP template (report Table 1)."""

    m: float
    l0: float
    k_c: float
    k_d: float
    g_s: float
    g_f: float
    q_r_td: float
    q_r_lo: float

    def __init__(
        self,
        m: float = 80.0,
        l0: float = 1.0,
        k: float | None = None,
        *,
        k_c: float | None = None,
        k_d: float | None = None,
        g_s: float = 9.81,
        g_f: float = 9.81,
        q_r_td: float | None = None,
        q_r_lo: float | None = None,
    ) -> None:
        if k is not None and (k_c is not None or k_d is not None):
            raise ValueError(
                f"SlipParams: give either k (both stiffnesses) or k_c/k_d, not both (got k={num(k)}, "
                f"k_c={num(k_c)}, k_d={num(k_d)})"
            )
        stiff = _DEFAULT_K if k is None else k
        values = {
            "m": m,
            "l0": l0,
            "k_c": stiff if k_c is None else k_c,
            "k_d": stiff if k_d is None else k_d,
            "g_s": g_s,
            "g_f": g_f,
            "q_r_td": q_r_td,
            "q_r_lo": q_r_lo,
        }
        # the argument a value came from: k_c and k_d name k when k set them
        given = {"k_c": "k" if k is not None else "k_c", "k_d": "k" if k is not None else "k_d"}
        for name, value in values.items():
            if value is None:
                continue
            if not is_real(value):
                raise ParamTypeError(given.get(name, name), "must be a real number", value)
            if not math.isfinite(value) or value <= 0.0:
                raise ParamError(given.get(name, name), "must be finite and positive", value)
            values[name] = float(value)
        for name in ("q_r_td", "q_r_lo"):
            if values[name] is None:
                values[name] = values["l0"]
            elif values[name] > values["l0"]:
                raise ParamError(
                    name, f"must not exceed the rest length l0={num(values['l0'])}", values[name]
                )
        for name, value in values.items():
            object.__setattr__(self, name, value)

    @property
    def constant_stiffness(self) -> bool:
        """True when k_c == k_d (the setting of the report's sections 3 and 4)."""
        return self.k_c == self.k_d

    @property
    def k(self) -> float:
        """The single stiffness of a constant-stiffness leg; ValueError when k_c != k_d."""
        if not self.constant_stiffness:
            raise ValueError(
                "this needs a constant leg stiffness (k_c == k_d), "
                f"got k_c={num(self.k_c)} != k_d={num(self.k_d)}"
            )
        return self.k_c

    def with_(self, **changes: float) -> SlipParams:
        """A copy with some fields changed (validated again); ``k=`` sets both stiffnesses."""
        if "k" in changes:
            k = changes.pop("k")
            changes.update(k_c=k, k_d=k)
        return replace(self, **changes)

    def as_dict(self) -> dict[str, float]:
        return {f.name: getattr(self, f.name) for f in fields(self)}


#: The documented default case: an 80 kg human runner with a 1 m leg and a 20 kN/m spring.
HUMAN_RUNNER = SlipParams(m=80.0, l0=1.0, k=20_000.0)

#: A small robot hopper (about 3 kg, 0.25 m leg, 1.5 kN/m): dimensionless stiffness k l0/(m g) ~ 13,
#: softer than the human runner's ~ 25, so its sweep angles and compressions are larger.
ROBOT_HOPPER = SlipParams(m=3.0, l0=0.25, k=1_500.0)
