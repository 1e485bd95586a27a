"""The SLIP parameters and the apex-return inputs, declared once, as plain data.

Every parameter (report Table 1) and every public input of the apex-return map is a row here:
its name, meaning, SI unit, default and domain. Everything else reads these rows: the kernel
arguments (:mod:`.catalog` gives each its SymPy symbol and run-time domain check),
``slipmaps.SlipParams`` (its fields, defaults and checks), the command line's flags (``--m``,
``--k-c`` ...), the sweep's quantities, the API's input checks and the Jacobians' column names.
Adding a parameter is adding its row (and using it in a declaration).

Plain data, no SymPy: the runtime imports this module (a wheel without the derive extra runs
without SymPy).

Domains (the checks both the kernels and the Python layer make):

- ``positive``: finite and > 0;
- ``leg_length``: finite, > 0 and <= l0 (a default of ``"l0"`` is the rest length);
- ``non_negative``: finite and >= 0;
- ``leg_angle``: finite and |x| < pi/2 (the leg above the ground);
- ``real``: finite.

A row with ``unmodelled`` is a parameter that only some maps model (those that declare it in their
``params``): a map that does not declare it assumes that value, and the Python layer refuses any
other for it (``runtime/api/index.py``: ``MapInfo.check_params``), naming the maps that take it.

An input's row may also hold a ``limit`` that depends on the parameters, ``{"sqrt_ratio": (a, b),
"why": ...}``: ``|x| <= sqrt(a / b)`` of parameters ``a`` and ``b`` (the retraction rate's
``sqrt(g_f/q_r_td)``). The kernel that needs it guards it (``INVALID_INPUT``:
:func:`.catalog.limit`), the Python layer checks it where a run or a plan takes the input and names
it and its range in a scalar call's ``INVALID_INPUT`` message (``runtime/api/validate.py``).
"""

from __future__ import annotations

__all__ = ["ALIASES", "APEX_INPUTS", "DOMAINS", "NEXT", "PARAMETERS", "public_output"]

DOMAINS = ("positive", "leg_length", "non_negative", "leg_angle", "real")

#: The SLIP parameters, in the order of ``SlipParams``' fields.
PARAMETERS: tuple[dict, ...] = (
    {"name": "m", "doc": "body mass", "unit": "kg", "default": 80.0, "domain": "positive"},
    {"name": "l0", "doc": "rest leg length", "unit": "m", "default": 1.0, "domain": "positive"},
    {
        "name": "k_c",
        "doc": "leg stiffness while compressing",
        "unit": "N/m",
        "default": 20_000.0,
        "domain": "positive",
    },
    {
        "name": "k_d",
        "doc": "leg stiffness after the bottom",
        "unit": "N/m",
        "default": 20_000.0,
        "domain": "positive",
    },
    {
        "name": "g_s",
        "doc": "gravitational acceleration in stance, positive (pointing down)",
        "unit": "m/s^2",
        "default": 9.81,
        "domain": "positive",
    },
    {
        "name": "g_f",
        "doc": "gravitational acceleration in flight, positive (pointing down)",
        "unit": "m/s^2",
        "default": 9.81,
        "domain": "positive",
    },
    {"name": "q_r_td", "doc": "touchdown leg length", "unit": "m", "default": "l0", "domain": "leg_length"},
    {"name": "q_r_lo", "doc": "liftoff leg length", "unit": "m", "default": "l0", "domain": "leg_length"},
    {
        "name": "c",
        "doc": "leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg)",
        "unit": "N s/m",
        "default": 0.0,
        "domain": "non_negative",
        "unmodelled": 0.0,
    },
)

#: Parameters that set others: ``k``, a constant stiffness (k_c = k_d = k), the kernel argument of
#: the maps that need one (report sections 3-4).
ALIASES: dict[str, dict] = {
    "k": {"doc": "leg stiffness, constant (k_c = k_d = k)", "unit": "N/m", "sets": ("k_c", "k_d")},
}

#: The public inputs of the apex-return map, by their API names, with the kernel argument each is.
APEX_INPUTS: tuple[dict, ...] = (
    {
        "name": "apex_height",
        "arg": "b_y_apex",
        "doc": "apex height of the body above the ground under it",
        "unit": "m",
        "domain": "non_negative",
    },
    {
        "name": "apex_speed",
        "arg": "b_xd_apex",
        "doc": "horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward "
        "+x, with the touchdown angle mirrored too); 0 is a hop in place",
        "unit": "m/s",
        "domain": "real",
    },
    {
        "name": "touchdown_angle",
        "arg": "q_th_td",
        "doc": "touchdown leg angle from the vertical, counterclockwise positive",
        "unit": "rad",
        "domain": "leg_angle",
    },
    {
        "name": "ground",
        "arg": "ground",
        "doc": "height of the touchdown ground above the ground under the apex (a step up is positive)",
        "unit": "m",
        "domain": "real",
        "default": 0.0,
    },
    {
        "name": "retraction_rate",
        "arg": "retraction_rate",
        "doc": "swing-leg retraction rate: after the apex the leg angle is touchdown_angle + "
        "retraction_rate * t (counterclockwise positive like the angle: a forward runner's retracting leg "
        "has a negative rate; Seyfarth, Geyer and Herr 2003); 0 holds the leg at touchdown_angle",
        "unit": "rad/s",
        "limit": {"sqrt_ratio": ("g_f", "q_r_td"), "why": "the foot's height concave in time"},
        "domain": "real",
        "default": 0.0,
    },
)

#: The prefix of a result value that is the next value of an input: the apex-return kernels write
#: the next apex as ``apex_height`` and ``apex_speed``, the names of two inputs above, and every
#: result of the API (and docs/maps.md) calls it ``next_apex_height``, ``next_apex_speed``
#: (slipmaps.runtime.api.names applies :func:`public_output`; the kernels keep their names).
NEXT = "next_"


def public_output(name: str) -> str:
    """A map output's public name: ``next_`` + its name when an apex-return input has that name."""
    return NEXT + name if any(r["name"] == name for r in APEX_INPUTS) else name
