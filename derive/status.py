"""Status codes shared by every generated kernel and the exact simulator.

This is the single definition: ``slipmaps generate`` renders it into ``generated/status.py``,
which kernels and the runtime import. Kernels never raise; they return NaN outputs plus one of
these codes, and the runtime turns a code into a message (``slipmaps.generated.status.MESSAGES``).
"""

from __future__ import annotations

#: (name, code, message). Codes are stable: append, never renumber.
STATUS_CODES: tuple[tuple[str, int, str], ...] = (
    ("OK", 0, "ok"),
    ("INVALID_INPUT", 1, "an input is not finite or outside its valid range"),
    ("APEX_TOO_LOW", 2, "the apex is not above the touchdown height q_r_td*cos(q_th_td): no touchdown"),
    (
        "TOUCHDOWN_NOT_COMPRESSING",
        3,
        "the leg is not compressing at touchdown (q_rd_td >= 0): no stance phase starts",
    ),
    (
        "NO_REAL_SOLUTION",
        4,
        "the radial quadrature (9)-(11) has no real solution (b^2 <= 0, negative discriminant)",
    ),
    (
        "TOUCHDOWN_OUTSIDE_OSCILLATION",
        5,
        "the touchdown leg length lies outside the approximate radial oscillation (11)",
    ),
    ("NO_LIFTOFF", 6, "the leg never extends back to the liftoff length q_r_lo"),
    ("FALL", 7, "the body reaches the ground (the leg passes horizontal) during stance"),
    ("LIFTOFF_DOWNWARD", 8, "the body moves downward at liftoff (b_yd <= 0): no flight phase"),
    ("LIFTOFF_BACKWARD", 9, "the body moves backward at liftoff (b_xd <= 0)"),
    (
        "RECOMPRESSION",
        10,
        "the leg starts compressing again after the bottom (the decompression stiffness k_d is too soft)",
    ),
    ("INTEGRATION_FAILED", 11, "the numerical integrator failed"),
    (
        "NUMERICAL_RANGE",
        12,
        "an output overflowed or is NaN (inputs far outside a physical range)",
    ),
    (
        "NOT_CONVERGED",
        13,
        "the fixed-point iteration did not converge within its bound (raise iterations or tol)",
    ),
    (
        "ENERGY_DEFICIT",
        14,
        "the approximate liftoff state needs more energy than the touchdown state has (no real q_rd_lo)",
    ),
    (
        "IMAGINARY_MOMENTUM",
        15,
        "the radial momentum p_r of an iterate is imaginary (H^{-1} of (33) or the radial work < 0: the "
        "iterate overshoots the turning point)",
    ),
    (
        "NO_TOUCHDOWN",
        16,
        "the swinging leg does not meet the ground from above with |q_th| < pi/2 (the retraction rate "
        "sweeps the foot away from the ground or the leg past the horizontal)",
    ),
    (
        "OVERDAMPED",
        17,
        "the leg damping reaches the critical damping of the approximate radial oscillation (delta >= "
        "omega_n): no damped oscillation to lift off from",
    ),
)
