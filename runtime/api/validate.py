"""Input validation shared by the runtime layer: every failure names the value.

A value that is not a real number (a string, bytes, None, a complex number) is a TypeError
(:class:`~.numeric.NotANumber`, also a ValueError); a real number out of its domain (NaN, negative,
|q_th| >= pi/2...) a ValueError. Messages show values plainly (:func:`~.numeric.num`: ``nan``,
``-1.0``, never ``np.float64(...)``).

Kernels never raise (they return status codes); the Python layer checks its inputs here first so
that a wrong argument fails loudly and clearly instead of turning into a NaN. An input whose range
depends on the parameters (its row's ``limit`` in ``derive/params.py``: the retraction rate's
``|rate| <= sqrt(g_f/q_r_td)``) is checked by :func:`within_limit` where a run or a plan takes it;
a map call leaves it to the kernel (``INVALID_INPUT``), and :func:`outside_limits` says why.
"""

from __future__ import annotations

import math

import numpy as np
from slipmaps.derive import params as _table

from .numeric import NotANumber, is_real, num
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
    """A finite float; TypeError when ``value`` is not a real number (a string, bytes, a bool...),
    ValueError when it is not finite, both naming ``name`` and the value."""
    if type(value) is float and math.isfinite(value):  # the common case, one check
        return value
    if not is_real(value):
        raise NotANumber(f"{name} must be a real number, got {type(value).__name__} {value!r}")
    x = float(value)  # type: ignore[arg-type]
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {num(x)}")
    return x


def non_negative(name: str, value: object) -> float:
    x = real(name, value)
    if x < 0.0:
        raise ValueError(f"{name} must not be negative, got {num(x)}")
    return x


def positive(name: str, value: object) -> float:
    x = real(name, value)
    if x <= 0.0:
        raise ValueError(f"{name} must be positive, got {num(x)}")
    return x


def leg_angle(name: str, value: object) -> float:
    x = real(name, value)
    if abs(x) >= math.pi / 2:
        raise ValueError(f"{name} must lie in (-pi/2, pi/2) (the leg above the ground), got {num(x)}")
    return x


def leg_length(name: str, value: object, l0: float | None = None) -> float:
    x = positive(name, value)
    if l0 is not None and x > l0:
        raise ValueError(f"{name} must not exceed the rest length l0={num(l0)}, got {num(x)}")
    return x


#: The check of each domain of ``derive/params.py`` (one line naming the value, ValueError).
CHECKS = {
    "real": real,
    "non_negative": non_negative,
    "positive": positive,
    "leg_angle": leg_angle,
    "leg_length": leg_length,
}


#: The apex-return inputs whose range depends on the parameters (their row's ``limit`` in
#: ``derive/params.py``, the kernels' guard): name -> the row.
LIMITED = {r["name"]: r for r in _table.APEX_INPUTS if "limit" in r}


def limit(name: str, params: SlipParams) -> float:
    """The bound of input ``name`` for ``params`` (its row's ``limit``: ``|x| <= sqrt(a / b)``)."""
    a, b = LIMITED[name]["limit"]["sqrt_ratio"]
    values = params.values()
    return math.sqrt(values[a] / values[b])


def limit_text(name: str, params: SlipParams) -> str:
    """The range of input ``name`` for ``params`` in words (6 significant digits): ``[-3.13209,
    3.13209] rad/s (|retraction_rate| <= sqrt(g_f/q_r_td): the foot's height concave in time)``."""
    row = LIMITED[name]
    bound = limit(name, params)
    a, b = row["limit"]["sqrt_ratio"]
    why = row["limit"]["why"]
    return f"[{-bound:.6g}, {bound:.6g}] {row['unit']} (|{name}| <= sqrt({a}/{b}): {why})"


def within_limit(label: str, name: str, value: object, params: SlipParams) -> float:
    """``value`` of input ``name`` (a finite number within its row's limit for ``params``); else
    ValueError naming ``label`` (the argument, key or flag as given) and the range."""
    x = real(label, value)
    if abs(x) > limit(name, params):
        raise ValueError(f"{label} must lie in {limit_text(name, params)}, got {num(x)}")
    return x


def outside_limits(params: SlipParams, inputs: dict) -> str | None:
    """Why a call's INVALID_INPUT status came from the inputs (by public name) that their rows'
    limits refuse, in one line naming each and its range; None when none is outside."""
    bad = [
        f"{name}={num(inputs[name])} is outside its range {limit_text(name, params)}"
        for name in LIMITED
        if name in inputs and is_real(inputs[name]) and abs(float(inputs[name])) > limit(name, params)
    ]
    return "; ".join(bad) or None


def real_array(name: str, value: object) -> np.ndarray:
    """``value`` as a float64 array (no copy when it already is one); TypeError when it holds
    strings, bytes or other non-numbers (numpy would parse ``"1.0"`` as 1.0)."""
    if type(value) is np.ndarray and value.dtype == np.float64:  # the common case: as it is
        return value
    arr = np.asarray(value)
    if arr.dtype.kind == "O":
        bad = next((v for v in arr.flat if not is_real(v)), None)
        if bad is not None:
            raise NotANumber(f"{name} must hold real numbers, got {type(bad).__name__} {bad!r}")
    elif arr.dtype.kind not in "biuf":
        raise NotANumber(f"{name} must hold real numbers, got an array of dtype {arr.dtype}")
    return arr.astype(float, copy=False)


def polar_state(params: SlipParams, state: object, what: str = "touchdown") -> PolarState:
    """Validate a polar stance state (q_r, q_rd, q_th, q_thd) with 0 < q_r <= l0 and |q_th| < pi/2."""
    if (
        (type(state) is tuple or type(state) is list)
        and len(state) == 4
        and not any(isinstance(v, (tuple, list, np.ndarray)) for v in state)
    ):
        values = state  # each entry checked as itself below: no array, and a bool refused
    else:
        if isinstance(state, (str, bytes)):
            raise NotANumber(f"{what} must be 4 numbers (q_r, q_rd, q_th, q_thd), got {state!r}")
        try:
            arr = real_array(what, state)
        except NotANumber:
            raise
        except ValueError:  # ragged
            raise ValueError(f"{what} must be 4 numbers (q_r, q_rd, q_th, q_thd), got {state!r}") from None
        if arr.shape != (4,):
            raise ValueError(
                f"{what} must be 4 numbers (q_r, q_rd, q_th, q_thd), got shape {arr.shape}: {state!r}"
            )
        values = arr.tolist()  # Python floats: real()'s one-check path
    q_r, q_rd, q_th, q_thd = values
    # the common case, finite Python floats, in one check; else each checked, naming a bad one
    if not (
        type(q_r) is float
        and type(q_rd) is float
        and type(q_th) is float
        and type(q_thd) is float
        and math.isfinite(q_r + q_rd + q_th + q_thd)
    ):
        q_r, q_rd, q_th, q_thd = (real(f"{what} {n}", v) for n, v in zip(POLAR_NAMES, values, strict=True))
    if not 0.0 < q_r <= params.l0 * (1.0 + L0_SLACK):
        raise ValueError(f"{what} q_r must lie in (0, l0={num(params.l0)}], got {num(q_r)}")
    leg_angle(f"{what} q_th", q_th)
    return (min(q_r, params.l0), q_rd, q_th, q_thd)


def float_array(name: str, value: object) -> np.ndarray:
    """A contiguous 1-D float64 array with every entry finite (ValueError naming the first bad one)."""
    arr = real_array(name, value)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array, got shape {arr.shape}")
    bad = np.flatnonzero(~np.isfinite(arr))
    if bad.size:
        raise ValueError(f"{name}[{bad[0]}] must be finite, got {num(arr[bad[0]])}")
    return np.ascontiguousarray(arr)
