"""The ``"exact"`` map: the numerical simulator in the result family of the maps.

Option ``method``: ``"compiled"`` (default) integrates with the numba-compiled DOP853 of
:mod:`.compiled` (batches in parallel over rows, microseconds per stance); ``"scipy"`` with
the ``solve_ivp`` reference :mod:`.reference` (batches loop over rows in Python, 1-2 ms per stance;
its messages name the failing stage and event). Both give the same statuses and agree to round-off
(tests/test_exact_compiled.py). :func:`trajectory` always samples the ``solve_ivp`` dense output.

Stance and apex-return results carry the same names as every generated map's (from the index),
so any two maps compare the same way; each batch row has its own status, and an invalid row is
``INVALID_INPUT``, never an exception.
"""

from __future__ import annotations

import math

import numpy as np
from slipmaps.generated.status import MESSAGES, Status

from ..api.params import SlipParams
from ..api.progress import progress as _progress
from ..api.results import GROUPS, Result, columns
from . import compiled as exact_compiled
from .compiled import STEP_NAMES
from .reference import StanceResult, StepResult, simulate_stance, simulate_step

#: The ``method`` option's reference choice; the other one (the default) is ``"compiled"``.
SCIPY = "scipy"

_NAN4 = (math.nan,) * 4


def _stance_values(r: StanceResult | StepResult) -> dict[str, float]:
    values = {"t_bottom": r.t_bottom, "t_stance": r.t_stance}
    for group, state in (("bottom", r.bottom), ("liftoff", r.liftoff)):
        values.update(zip(GROUPS[group], state or _NAN4, strict=True))
    return values


def _stance_row(r: StanceResult) -> list[float]:
    values = _stance_values(r)
    return [float(values[n]) for n in columns("stance")]


def _step_values(r: StepResult) -> dict[str, float]:
    return {
        **_stance_values(r),
        "apex_height": r.next_apex[0],
        "apex_speed": r.next_apex[1],
        "t_descent": r.t_descent,
        "t_ascent": r.t_ascent,
    }


def _apex_row(r: StepResult) -> list[float]:
    values = _step_values(r)
    return [float(values[n]) for n in columns("apex_return")]


def step_row(r: StepResult) -> list[float]:
    """An exact step's stance and apex-return values in the order of :data:`STEP_NAMES`, NaN unless
    the step completed (as a map's batch row)."""
    values = _step_values(r)
    return _masked([float(values[n]) for n in STEP_NAMES], r.status)


def _masked(row: list[float], status: Status) -> list[float]:
    """NaN everywhere unless OK, as the generated kernels do (partial exact results stay in the
    scalar result's simulator object, not in the row)."""
    return row if status == Status.OK else [math.nan] * len(row)


def stance(params: SlipParams, td, inputs: dict, method: str, rtol: float, atol: float) -> Result:
    if method != SCIPY:
        status, values = exact_compiled.stance_values(params, td, rtol, atol)
        return Result("exact", "stance", status, MESSAGES[int(status)], values, inputs)
    r = simulate_stance(params, td, rtol=rtol, atol=atol)
    row = _masked(_stance_row(r), r.status)
    return Result(
        "exact", "stance", r.status, r.message, dict(zip(columns("stance"), row, strict=True)), inputs
    )


def apex_return(
    params: SlipParams, h: float, v: float, th: float, inputs: dict, method: str, rtol: float, atol: float
) -> Result:
    if method != SCIPY:
        status, values = exact_compiled.step_values(params, h, v, th, rtol, atol)
        apex = {n: values[n] for n in columns("apex_return")}
        return Result("exact", "apex_return", status, MESSAGES[int(status)], apex, inputs)
    r = simulate_step(params, h, v, th, rtol=rtol, atol=atol)
    row = _masked(_apex_row(r), r.status)
    return Result(
        "exact",
        "apex_return",
        r.status,
        r.message,
        dict(zip(columns("apex_return"), row, strict=True)),
        inputs,
    )


def _select(data: np.ndarray, have: tuple[str, ...], names) -> np.ndarray:
    """The columns ``names`` of ``data`` whose columns are ``have`` (no copy when they coincide)."""
    names = tuple(names)
    if names == have:
        return data
    return data[:, [have.index(n) for n in names]]


def _rows(n: int, names, label: str, show, one) -> tuple[np.ndarray, np.ndarray]:
    data = np.full((n, len(names)), math.nan)
    status = np.empty(n, dtype=np.int64)
    for i in _progress(range(n), n, label, show):
        try:
            code, row = one(i)
        except ValueError:
            code, row = Status.INVALID_INPUT, None
        status[i] = int(code)
        if code == Status.OK:
            data[i] = row
    return data, status


def stance_rows(params: SlipParams, arr: np.ndarray, names, show, method: str, rtol: float, atol: float):
    if method != SCIPY:
        data, status = exact_compiled.stance_rows(params, arr, rtol, atol)
        return _select(data, exact_compiled.STANCE_NAMES, names), status

    def one(i):
        r = simulate_stance(params, arr[i], rtol=rtol, atol=atol)
        return r.status, _stance_row(r)

    return _rows(arr.shape[0], names, "exact stance", show, one)


def apex_rows(params: SlipParams, cols, names, show, method: str, rtol: float, atol: float):
    h, v, th = cols
    if method != SCIPY:
        data, status = exact_compiled.step_rows(params, h, v, th, rtol, atol)
        return _select(data, STEP_NAMES, names), status

    def one(i):
        r = simulate_step(params, h[i], v[i], th[i], rtol=rtol, atol=atol)
        return r.status, _apex_row(r)

    return _rows(h.shape[0], names, "exact apex return", show, one)


def trajectory(params: SlipParams, td, method: str, rtol: float, atol: float):
    """The solve_ivp dense output for either ``method`` (the compiled simulator keeps no samples)."""
    r = simulate_stance(params, td, dense=True, rtol=rtol, atol=atol)
    states = r.states.T if r.states is not None else np.empty((0, 4))
    return (r.t if r.t is not None else np.empty(0)), states, r.status


__all__ = ["STEP_NAMES", "stance", "apex_return", "stance_rows", "apex_rows", "step_row", "trajectory"]
