"""Input validation shared by the runtime layer: every failure is a ValueError naming the value.

Kernels never raise (they return status codes); the Python layer checks its inputs here first so
that a wrong argument fails loudly and clearly instead of turning into a NaN.
"""

from __future__ import annotations

import math

import numpy as np

from .params import SlipParams

PolarState = tuple[float, float, float, float]
POLAR_NAMES = ("q_r", "q_rd", "q_th", "q_thd")
#: Touchdown leg lengths up to ``l0 * (1 + L0_SLACK)`` are accepted (round-off of conversions).
L0_SLACK = 1e-12


def check_params(params: object) -> SlipParams:
    if not isinstance(params, SlipParams):
        raise TypeError(f"params must be a SlipParams, got {type(params).__name__}: {params!r}")
    return params


def real(name: str, value: object) -> float:
    """A finite float, or ValueError naming ``name`` and the value."""
    if isinstance(value, bool):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x


def non_negative(name: str, value: object) -> float:
    x = real(name, value)
    if x < 0.0:
        raise ValueError(f"{name} must not be negative, got {value!r}")
    return x


def positive(name: str, value: object) -> float:
    x = real(name, value)
    if x <= 0.0:
        raise ValueError(f"{name} must be positive, got {value!r}")
    return x


def leg_angle(name: str, value: object) -> float:
    x = real(name, value)
    if abs(x) >= math.pi / 2:
        raise ValueError(f"{name} must satisfy |{name}| < pi/2 (leg above the ground), got {value!r}")
    return x


def polar_state(params: SlipParams, state: object, what: str = "touchdown") -> PolarState:
    """Validate a polar stance state (q_r, q_rd, q_th, q_thd) with 0 < q_r <= l0 and |q_th| < pi/2."""
    if isinstance(state, (str, bytes)):
        raise ValueError(f"{what} must be 4 numbers (q_r, q_rd, q_th, q_thd), got {state!r}")
    try:
        arr = np.asarray(state, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{what} must be 4 numbers (q_r, q_rd, q_th, q_thd), got {state!r}") from None
    if arr.shape != (4,):
        raise ValueError(
            f"{what} must be 4 numbers (q_r, q_rd, q_th, q_thd), got shape {arr.shape}: {state!r}"
        )
    q_r, q_rd, q_th, q_thd = (real(f"{what} {n}", v) for n, v in zip(POLAR_NAMES, arr, strict=True))
    if not 0.0 < q_r <= params.l0 * (1.0 + L0_SLACK):
        raise ValueError(f"{what} q_r must lie in (0, l0={params.l0!r}], got {q_r!r}")
    leg_angle(f"{what} q_th", q_th)
    return (min(q_r, params.l0), q_rd, q_th, q_thd)


def float_array(name: str, value: object) -> np.ndarray:
    """A contiguous 1-D float64 array with every entry finite (ValueError naming the first bad one)."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array, got shape {arr.shape}")
    bad = np.flatnonzero(~np.isfinite(arr))
    if bad.size:
        raise ValueError(f"{name}[{bad[0]}] must be finite, got {arr[bad[0]]!r}")
    return np.ascontiguousarray(arr)
