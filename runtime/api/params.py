"""SLIP parameters (report Table 1), validated on construction.

Units are SI throughout: kg, m, N/m, m/s^2, N s/m. ``SlipParams(m=80, l0=1, k=20_000)`` gives a
leg of constant stiffness ``k``; ``k_c`` / ``k_d`` set the stiffness while the leg compresses (until
the bottom) and after the bottom separately (report section 5). ``g_s`` is the gravitational
acceleration during stance, ``g_f`` during flight (both positive numbers, pointing down).
``q_r_td`` and ``q_r_lo`` are the touchdown and liftoff leg lengths; both default to the rest
length ``l0`` and must lie in (0, l0]; :meth:`SlipParams.with_` keeps a leg length that is at the
rest length there, so ``HUMAN_RUNNER.with_(l0=0.6)`` has 0.6 m ones. ``c`` is the leg damping
(default 0, >= 0; not in the report: only the maps that declare it model it, the others refuse
c != 0). Every field defaults to the human runner (:data:`HUMAN_RUNNER`: 80 kg, 1 m leg, 20 kN/m).
A value that is not a real number (a string, say) is a TypeError (:class:`ParamTypeError`, also a
ValueError), one out of its domain a ValueError (:class:`ParamError`); both name the argument given
(``k`` when ``k`` set both stiffnesses). An unknown argument is a TypeError naming ``SlipParams``
and its arguments.
"""

from __future__ import annotations

import inspect
import math

from slipmaps.derive import params as _table

from .numeric import NotANumber, is_real, num

__all__ = [
    "FIELDS",
    "HUMAN_RUNNER",
    "PARAMETERS",
    "ParamError",
    "ParamTypeError",
    "ROBOT_HOPPER",
    "SlipParams",
]


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


#: The parameter table (``derive/params.py``, plain data): every field of :class:`SlipParams` and the
#: alias ``k``, with its meaning, unit, default and domain. Nothing here restates it.
PARAMETERS: tuple[dict, ...] = _table.PARAMETERS
ALIASES: dict[str, dict] = _table.ALIASES
FIELDS: tuple[str, ...] = tuple(r["name"] for r in PARAMETERS)
_ROWS = {r["name"]: r for r in PARAMETERS}
#: What each domain of the table asks of a field, in its error message (a leg length's bound by l0
#: is checked after all fields are read).
_DOMAIN_WORDS = {
    "positive": "must be finite and positive",
    "leg_length": "must be finite and positive",
    "non_negative": "must be finite and non-negative",
}


def _signature() -> inspect.Signature:
    """``SlipParams(m=80.0, l0=1.0, k=None, *, k_c=None, ...)``: the table's first two fields and
    ``k`` positional, the rest keyword-only; defaults the table's (None where it defaults to l0 or
    where ``k`` may set it)."""
    P = inspect.Parameter
    sets = {n for a in ALIASES.values() for n in a["sets"]}
    out = [P("self", P.POSITIONAL_OR_KEYWORD)]
    for name in FIELDS[:2]:
        out.append(P(name, P.POSITIONAL_OR_KEYWORD, default=_ROWS[name]["default"]))
    out += [P(name, P.POSITIONAL_OR_KEYWORD, default=None) for name in ALIASES]
    for name in FIELDS[2:]:
        default = None if name in sets or isinstance(_ROWS[name]["default"], str) else _ROWS[name]["default"]
        out.append(P(name, P.KEYWORD_ONLY, default=default))
    return inspect.Signature(out)


class SlipParams:
    """Physical parameters of the SLIP template (report Table 1), validated on construction.

    Fields (``derive/params.py``): m [kg], l0 [m], k_c and k_d [N/m], g_s and g_f [m/s^2], q_r_td
    and q_r_lo [m], the leg damping c [N s/m] (default 0); ``k=`` sets k_c = k_d. Frozen, hashable,
    compared by value."""

    __slots__ = (*FIELDS, "_k", "_h")

    def __init__(self, *args, **kwargs) -> None:
        try:
            bound = _SIGNATURE.bind(self, *args, **kwargs)
        except TypeError as exc:  # an unknown or repeated argument: name the class and its arguments
            raise TypeError(f"SlipParams: {exc}; its arguments: {', '.join(_ARGUMENTS)}") from None
        bound.apply_defaults()
        given = dict(bound.arguments)
        given.pop("self")
        aliases = {name: given.pop(name) for name in ALIASES}
        origin = {}  # the argument a value came from: k_c and k_d name k when k set them
        for alias, value in aliases.items():
            if value is None:
                continue
            sets = ALIASES[alias]["sets"]
            clash = {n: given[n] for n in sets if given[n] is not None}
            if clash:
                others = ", ".join(f"{n}={num(v)}" for n, v in clash.items())
                raise ValueError(
                    f"SlipParams: give either {alias} (both stiffnesses) or {'/'.join(sets)}, not both "
                    f"(got {alias}={num(value)}, {others})"
                )
            for n in sets:
                given[n], origin[n] = value, alias
        for name in FIELDS:
            if given[name] is None and not isinstance(_ROWS[name]["default"], str):
                given[name] = _ROWS[name]["default"]
        for name in FIELDS:
            value = given[name]
            if value is None:
                continue
            if not is_real(value):
                raise ParamTypeError(origin.get(name, name), "must be a real number", value)
            if (
                not math.isfinite(value)
                or value < 0.0
                or (value == 0.0 and _ROWS[name]["domain"] != "non_negative")
            ):
                raise ParamError(origin.get(name, name), _DOMAIN_WORDS[_ROWS[name]["domain"]], value)
            given[name] = float(value)
        for name in FIELDS:
            default = _ROWS[name]["default"]
            if isinstance(default, str):  # a leg length: defaults to (and must not exceed) l0
                if given[name] is None:
                    given[name] = given[default]
                elif given[name] > given[default]:
                    raise ParamError(
                        name, f"must not exceed the rest length {default}={num(given[default])}", given[name]
                    )
        for name in FIELDS:
            object.__setattr__(self, name, given[name])
        # the key and hash once (every map call hashes its parameters to find its cached Call)
        object.__setattr__(self, "_k", tuple(given[n] for n in FIELDS))
        object.__setattr__(self, "_h", hash(self._k))

    def __setattr__(self, name, value):
        raise AttributeError(f"SlipParams is frozen: use .with_({name}=...) for a changed copy")

    def __delattr__(self, name):
        raise AttributeError("SlipParams is frozen")

    def _key(self) -> tuple[float, ...]:
        return self._k

    def __eq__(self, other):
        return type(other) is SlipParams and self._k == other._k

    def __hash__(self):
        return self._h

    def __repr__(self):
        return "SlipParams(" + ", ".join(f"{n}={getattr(self, n)!r}" for n in FIELDS) + ")"

    def __reduce__(self):
        return (_rebuild, (self.as_dict(),))

    @property
    def constant_stiffness(self) -> bool:
        """True when k_c == k_d (the setting of the report's sections 3 and 4)."""
        return self.k_c == self.k_d

    @property
    def conserves_energy(self) -> bool:
        """True when a step keeps the flight energy m (g_f h + v^2/2), that is when k_c == k_d,
        g_s == g_f, q_r_td == q_r_lo and there is no leg damping (c == 0)."""
        same = self.g_s == self.g_f and self.q_r_td == self.q_r_lo
        return self.constant_stiffness and same and self.c == 0.0

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
        """A copy with some fields changed (validated again); ``k=`` sets both stiffnesses. A leg
        length not given that is at its rest length follows it (``with_(l0=0.6)`` of a 1 m leg at
        rest lengths has 0.6 m ones), as a length not given to :class:`SlipParams` does."""
        values = self.as_dict()
        unknown = sorted(set(changes) - set(values) - set(ALIASES))
        if unknown:
            raise TypeError(
                f"SlipParams has no field(s) {', '.join(unknown)}; its arguments: {', '.join(_ARGUMENTS)}"
            )
        for alias, a in ALIASES.items():
            if alias in changes:
                for n in a["sets"]:
                    values.pop(n)
        for name in FIELDS:
            rest = _ROWS[name]["default"]  # "l0" for a leg length
            if isinstance(rest, str) and rest in changes and name not in changes:
                if values[name] == values[rest]:
                    values.pop(name)  # at the rest length: defaults to the new one
        return SlipParams(**{**values, **changes})

    def as_dict(self) -> dict[str, float]:
        return {n: getattr(self, n) for n in FIELDS}

    def values(self) -> dict[str, float]:
        """Every kernel parameter by name: the fields, and each alias (``k``) whose fields agree."""
        out = self.as_dict()
        for alias, a in ALIASES.items():
            first = out[a["sets"][0]]
            if all(out[n] == first for n in a["sets"]):
                out[alias] = first
        return out


_SIGNATURE = _signature()
#: The arguments of :class:`SlipParams`, in its signature's order (for the messages).
_ARGUMENTS = tuple(p for p in _SIGNATURE.parameters if p != "self")
SlipParams.__init__.__signature__ = _SIGNATURE


def _rebuild(values: dict) -> SlipParams:
    return SlipParams(**values)


#: The documented default case: an 80 kg human runner with a 1 m leg and a 20 kN/m spring.
HUMAN_RUNNER = SlipParams(m=80.0, l0=1.0, k=20_000.0)

#: A small robot hopper (about 3 kg, 0.25 m leg, 1.5 kN/m): dimensionless stiffness k l0/(m g) ~ 13,
#: softer than the human runner's ~ 25, so its sweep angles and compressions are larger.
ROBOT_HOPPER = SlipParams(m=3.0, l0=0.25, k=1_500.0)
