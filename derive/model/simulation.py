"""The exact simulator's numerical settings, declared once (plain data).

The compiled simulator (generated/exact_stance.py, rendered from derive/templates/) and the
``solve_ivp`` reference (runtime/exact/reference.py, through the generated index's ``EXACT``) read
these; the step cap and the stance time limit are kernels of the model (derive/model/kernels.py:
``max_step``, ``stance_time_limit``) built from them.
"""

from __future__ import annotations

__all__ = [
    "COLLAPSE_FRACTION",
    "DEFAULT_ATOL",
    "DEFAULT_RTOL",
    "MAX_STEP_FRACTION",
    "SETTINGS",
    "T_MAX_PERIODS",
]

#: Default relative and absolute tolerances of the DOP853 integration.
DEFAULT_RTOL = 1e-11
DEFAULT_ATOL = 1e-12
#: The stance ends with FALL when the leg length drops to this fraction of l0.
COLLAPSE_FRACTION = 1e-3
#: The stance time limit: this many (spring + pendulum) periods; a stance still on the ground then
#: is NO_LIFTOFF.
T_MAX_PERIODS = 20
#: A step is at most this fraction of the shorter natural period of its subphase (at the default
#: rtol; the compiled simulator scales it with the tolerance).
MAX_STEP_FRACTION = 1.0 / 16.0

#: Every setting by name (the index's ``EXACT["simulation"]``).
SETTINGS = {
    "DEFAULT_RTOL": DEFAULT_RTOL,
    "DEFAULT_ATOL": DEFAULT_ATOL,
    "COLLAPSE_FRACTION": COLLAPSE_FRACTION,
    "T_MAX_PERIODS": T_MAX_PERIODS,
    "MAX_STEP_FRACTION": MAX_STEP_FRACTION,
}
