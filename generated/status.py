# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/status.py
# Template:  derive/templates/status.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""Status codes returned by every generated kernel and by the exact simulator.

Kernels return NaN outputs plus one of these codes instead of raising; the runtime turns a code
into a message with :data:`MESSAGES`.
"""

from enum import IntEnum


class Status(IntEnum):
    """Outcome of a kernel call or a simulation: an int (its code) that prints its name
    (``str(Status.OK) == "OK"``, also in f-strings; ``int(Status.OK) == 0``)."""

    OK = 0
    INVALID_INPUT = 1
    APEX_TOO_LOW = 2
    TOUCHDOWN_NOT_COMPRESSING = 3
    NO_REAL_SOLUTION = 4
    TOUCHDOWN_OUTSIDE_OSCILLATION = 5
    NO_LIFTOFF = 6
    FALL = 7
    LIFTOFF_DOWNWARD = 8
    LIFTOFF_BACKWARD = 9
    RECOMPRESSION = 10
    INTEGRATION_FAILED = 11
    NUMERICAL_RANGE = 12
    NOT_CONVERGED = 13
    ENERGY_DEFICIT = 14
    IMAGINARY_MOMENTUM = 15
    NO_TOUCHDOWN = 16
    OVERDAMPED = 17

    def __str__(self) -> str:
        return self.name

    def __format__(self, spec: str) -> str:
        # a numeric spec (d, x, ...) formats the code; any other the name
        if spec and spec[-1] in "bcdoxXn":
            return int.__format__(int(self), spec)
        return format(self.name, spec)


# The codes as plain ints, which the generated kernel modules import (numba freezes a module-level
# int into the machine code it caches; the codes are fixed, so such a cache stays valid).
STATUS_OK = 0
STATUS_INVALID_INPUT = 1
STATUS_APEX_TOO_LOW = 2
STATUS_TOUCHDOWN_NOT_COMPRESSING = 3
STATUS_NO_REAL_SOLUTION = 4
STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION = 5
STATUS_NO_LIFTOFF = 6
STATUS_FALL = 7
STATUS_LIFTOFF_DOWNWARD = 8
STATUS_LIFTOFF_BACKWARD = 9
STATUS_RECOMPRESSION = 10
STATUS_INTEGRATION_FAILED = 11
STATUS_NUMERICAL_RANGE = 12
STATUS_NOT_CONVERGED = 13
STATUS_ENERGY_DEFICIT = 14
STATUS_IMAGINARY_MOMENTUM = 15
STATUS_NO_TOUCHDOWN = 16
STATUS_OVERDAMPED = 17

#: Human-readable message for each status code.
MESSAGES = {
    0: "ok",
    1: "an input is not finite or outside its valid range",
    2: "the apex is not above the touchdown height q_r_td*cos(q_th_td): no touchdown",
    3: "the leg is not compressing at touchdown (q_rd_td \u003e= 0): no stance phase starts",
    4: "the radial quadrature (9)-(11) has no real solution (b^2 \u003c= 0, negative "
        "discriminant)",
    5: "the touchdown leg length lies outside the approximate radial oscillation (11)",
    6: "the leg never extends back to the liftoff length q_r_lo",
    7: "the body reaches the ground (the leg passes horizontal) during stance",
    8: "the body moves downward at liftoff (b_yd \u003c= 0): no flight phase",
    9: "the body moves backward at liftoff (b_xd \u003c= 0)",
    10: "the leg starts compressing again after the bottom (the decompression stiffness "
        "k_d is too soft)",
    11: "the numerical integrator failed",
    12: "an output overflowed or is NaN (inputs far outside a physical range)",
    13: "the fixed-point iteration did not converge within its bound (raise iterations or "
        "tol)",
    14: "the approximate liftoff state needs more energy than the touchdown state has (no "
        "real q_rd_lo)",
    15: "the radial momentum p_r of an iterate is imaginary (H^{-1} of (33) or the radial "
        "work \u003c 0: the iterate overshoots the turning point)",
    16: "the swinging leg does not meet the ground from above with |q_th| \u003c pi/2 (the "
        "retraction rate sweeps the foot away from the ground or the leg past the "
        "horizontal)",
    17: "the leg damping reaches the critical damping of the approximate radial "
        "oscillation (delta \u003e= omega_n): no damped oscillation to lift off from",
}
