"""The public map API, generic over every map of the index (``slipmaps.maps()``) and ``"exact"``.

- :func:`stance`: polar touchdown state ``(q_r, q_rd, q_th, q_thd)`` -> bottom and liftoff states,
  ``t_bottom``, ``t_stance`` (times from touchdown) and the map's extras.
- :func:`apex_return`: apex ``(height [m], signed speed [m/s])``, touchdown leg angle [rad] and the
  ``ground`` under the touchdown [m] -> the next apex (``next_apex_height`` above the new ground,
  ``next_apex_speed``; :mod:`.names`), flight and stance times, liftoff state, ``step_length`` and
  the foot's position (``foot_x``, ``foot_y``) relative to the apex; the flights are exact
  (ballistic, ``g_f``), only the stance differs between maps. A negative speed runs toward -x,
  the mirror image of running toward +x with the touchdown angle mirrored (every map is mirror
  symmetric to round-off).
- :func:`stance_batch`, :func:`apex_return_batch`: the same over arrays, in parallel (the exact
  map's ``method="scipy"`` loops in Python); every row gets its own status, and a bad row (NaN,
  out of domain) gets ``INVALID_INPUT`` without failing the others. Apex-return inputs broadcast
  against each other; a batch result carries them (``inputs``, and its ``to_pandas()`` columns).
- :func:`trajectory`: the polar state along the stance.
- :func:`half_stance`, :func:`half_stance_batch`: a half-stance map (``slipmaps maps`` lists them):
  the touchdown state -> ``t_half`` and the bottom state (compression, k_c), or a bottom state
  ``(q_r, q_rd, q_th, q_thd)`` (q_rd ignored: 0 at the bottom) -> ``t_half`` and the liftoff state
  (decompression, k_d); ``res.end`` is the end state. A controller picks k_d between the two calls.

Every call fills the kernels' arguments by name (:mod:`.calls`): no function here knows an
argument order or branches on a map; the exact map is one like the others. Options are keywords
(``iterations=20``, ``reading="mean"``; ``slipmaps maps`` lists them). A scalar call raises
ValueError for an invalid argument (naming it); a state outside the map's domain is a result with a
status, never an exception (``INVALID_INPUT`` for a retraction rate beyond the range the parameters
give it: its message names the input and the range). Conventions (docs/conventions.md): SI units,
leg angle from the vertical, counterclockwise positive.
"""

from __future__ import annotations

import math

import numpy as np
from slipmaps.derive import params as _table
from slipmaps.generated.status import MESSAGES, Status

from . import memory
from .calls import Call, Columns
from .index import maps
from .inputs import apex_signature
from .params import SlipParams
from .results import BatchResult, Result
from .validate import CHECKS, L0_SLACK, float_array, outside_limits, polar_state, real_array

__all__ = [
    "maps",
    "stance",
    "stance_batch",
    "apex_return",
    "apex_return_batch",
    "trajectory",
    "half_stance",
    "half_stance_batch",
    "apex_inputs",
    "apex_rows",
    "batch_result",
    "state_rows",
    "touchdown_inputs",
]

#: The apex-return inputs (``derive/params.py``): API name -> kernel argument, check and default.
APEX_INPUTS = {r["name"]: r for r in _table.APEX_INPUTS}
#: API name -> (kernel argument, the check of its domain).
_APEX_ARGS = {k: (r["arg"], CHECKS[r["domain"]]) for k, r in APEX_INPUTS.items()}


def _result(call: Call, role: str, status: Status, row, inputs: dict, message: str | None = None) -> Result:
    names = call.spec(role).public_outputs
    # a row is the kernel's outputs, one per name (the layout's width)
    values = dict(zip(names, row, strict=False)) if status == Status.OK else dict.fromkeys(names, math.nan)
    return Result.of(call.info.name, role, status, message or MESSAGES[int(status)], values, inputs)


def touchdown_inputs(call: Call, state) -> dict[str, float]:
    """A validated polar state (:func:`~.validate.polar_state`) by the role's state arguments."""
    return dict(zip(call.spec("stance").x, state, strict=True))


def apex_inputs(given: dict) -> tuple[dict[str, float], dict[str, object]]:
    """The apex-return inputs, each checked by its domain (one line naming it): by kernel argument
    (the kernel's), and by public name (the result's ``inputs``)."""
    inputs, point = {}, {}
    for k, v in given.items():
        arg, check = _APEX_ARGS[k]
        inputs[arg] = point[k] = check(k, v)
    return inputs, point


def stance(name: str, params: SlipParams, touchdown, **options) -> Result:
    """One stance of map ``name`` from the polar touchdown state ``touchdown``."""
    call = Call.of(name, params, options)
    td = polar_state(params, touchdown)
    status, row, message = call.scalar("stance", touchdown_inputs(call, td))
    return _result(call, "stance", status, row, {"touchdown": td, "options": dict(call.options)}, message)


@apex_signature
def apex_return(name: str, params: SlipParams, given: dict, **options) -> Result:
    """One step of map ``name``: apex -> touchdown (leg at ``touchdown_angle``, on ground ``ground``
    higher) -> stance -> next apex (module docstring; the inputs are the table's: ``APEX_INPUTS`` of
    derive/params.py)."""
    call = Call.of(name, params, options)
    inputs, point = apex_inputs(given)
    status, row, message = call.scalar("apex_return", inputs)
    if status == Status.INVALID_INPUT and message is None:  # an input outside its range: which
        message = outside_limits(params, point)
    point["options"] = dict(call.options)
    return _result(call, "apex_return", status, row, point, message)


def state_rows(params: SlipParams, states, what: str = "touchdowns", call: Call | None = None, role=None):
    """(n, 4) float64 polar states (touchdown or bottom); leg lengths within round-off above l0 are
    l0, as in :func:`stance` (the only copy made: when such a row exists). With a ``call``, the
    memory a batch of its ``role`` needs for those rows is checked first (``Call.check_memory``),
    before any array of them is made."""
    arr = real_array(what, states)
    if arr.ndim != 2 or arr.shape[1] != 4:
        raise ValueError(f"{what} must have shape (n, 4) (q_r, q_rd, q_th, q_thd), got {arr.shape}")
    if call is not None and arr.shape[0] > memory.FEW_ROWS:
        call.check_memory(role, arr.shape[0])
    above = arr[:, 0] > params.l0
    if above.any():
        snap = above & (arr[:, 0] <= params.l0 * (1.0 + L0_SLACK))
        if snap.any():
            arr = arr.copy()
            arr[snap, 0] = params.l0
    return arr


def batch_result(
    call: Call, role: str, out: np.ndarray, status: np.ndarray, shape, given=None
) -> BatchResult:
    """The :class:`~.results.BatchResult` of a role's rows (``Call.batch``'s ``make``), with the
    inputs ``given`` (by name, broadcasting to ``shape``)."""
    return BatchResult(call.info.name, role, call.spec(role).public_outputs, out, status, shape, given)


def stance_batch(
    name: str, params: SlipParams, touchdowns, *, progress: bool | None = None, **options
) -> BatchResult:
    """Map ``name`` over touchdown states of shape (n, 4); a status per row. Its memory need is
    checked first; Ctrl-C raises :class:`~slipmaps.BatchInterrupted` with the rows finished."""
    call = Call.of(name, params, options)
    arr = state_rows(params, touchdowns, call=call, role="stance")
    td = Columns(arr, call.spec("stance").x)
    return call.batch("stance", td, {}, arr.shape[:1], batch_result, progress, given=td)


def apex_rows(
    given: dict, call: Call | None = None, role=None
) -> tuple[dict, dict[str, float], tuple[int, ...]]:
    """The apex-return inputs (by API name) broadcast against each other: ``(rows, inputs, shape)``,
    by kernel argument ``rows`` the inputs given as arrays, flattened to the rows of the broadcast
    ``shape``, and ``inputs`` those given as numbers (one value for every row: not copied per
    row). With a ``call``, the memory a batch of its ``role`` needs for those rows is checked first
    (``Call.check_memory``), before any row is copied."""
    arrays, inputs = {}, {}
    for key, x in given.items():
        arg = _APEX_ARGS[key][0]
        if type(x) is float:  # a number (the defaults among them): no array
            inputs[arg] = x
            continue
        arr = real_array(key, x)
        if arr.ndim:
            arrays[arg] = arr
        else:
            inputs[arg] = float(arr)
    shapes = {x.shape for x in arrays.values()}
    one = len(shapes) == 1
    shape = next(iter(shapes)) if one else np.broadcast_shapes(*shapes)
    n = math.prod(shape)
    if call is not None and n > memory.FEW_ROWS:
        call.check_memory(role, n)
    if one and len(shape) == 1:  # arrays of one 1-D shape (the common call): the rows as they are
        return arrays, inputs, shape
    rows = {
        a: x if x.shape == (n,) else (x if x.shape == shape else np.broadcast_to(x, shape)).reshape(n)
        for a, x in arrays.items()
    }
    return rows, inputs, shape


@apex_signature
def apex_return_batch(
    name: str, params: SlipParams, given: dict, *, progress: bool | None = None, **options
) -> BatchResult:
    """Map ``name`` over apexes, touchdown angles and grounds (arrays broadcast); a status per row.

    The result's columns have the broadcast shape of the inputs. The memory the rows need is checked
    before any is copied (ValueError, one line with the estimate); Ctrl-C raises
    :class:`~slipmaps.BatchInterrupted`, whose ``result`` holds the rows finished.
    """
    call = Call.of(name, params, options)
    rows, inputs, shape = apex_rows(given, call, "apex_return")
    # the inputs as given, by public name (apex_rows has checked them): broadcast when read
    return call.batch("apex_return", rows, inputs, shape, batch_result, progress, given=given)


def trajectory(
    name: str, params: SlipParams, touchdown, t=None, **options
) -> tuple[np.ndarray, np.ndarray, Status]:
    """The stance of map ``name`` from ``touchdown``: ``(t, states, status)``.

    ``states`` has shape (len(t), 4): q_r, q_rd, q_th, q_thd at the times ``t`` after touchdown
    (default: 200 points from touchdown to the map's liftoff); ``status`` the first failing one.
    """
    call = Call.of(name, params, options)
    td = polar_state(params, touchdown)
    if not call.info.has_trajectory:
        with_one = ", ".join(m.name for m in maps() if m.has_trajectory)
        raise ValueError(
            f"map {call.info.name!r} has no trajectory: it computes its event states only (touchdown, "
            f"bottom, liftoff: slipmaps.stance); maps with a trajectory: {with_one}"
        )
    if t is None:
        res = stance(name, params, td, **options)
        if not res.ok:
            return np.empty(0), np.empty((0, 4)), res.status
        t = np.linspace(0.0, res.t_stance, 200)
    times = float_array("t", np.atleast_1d(t))
    out, status = call.rows("state_at", {"t": times}, touchdown_inputs(call, td), times.shape[0])
    bad = status[status != int(Status.OK)]
    return times, out, Status(int(bad[0])) if bad.size else Status.OK


def half_stance(name: str, params: SlipParams, state, **options) -> Result:
    """One half of the stance by half-stance map ``name`` from its start state (polar, SI): the
    touchdown state for a compression half, a bottom state for a decompression half."""
    call = Call.of(name, params, options, half=True)
    start = polar_state(params, state, what=f"{call.info.start} state")
    status, row, message = call.scalar("half", dict(zip(call.spec("half").x, start, strict=True)))
    return _result(
        call, "half", status, row, {call.info.start: start, "options": dict(call.options)}, message
    )


def half_stance_batch(name: str, params: SlipParams, states, **options) -> BatchResult:
    """Half-stance map ``name`` over start states of shape (n, 4); a status per row. Its memory need
    is checked first; Ctrl-C raises :class:`~slipmaps.BatchInterrupted` with the rows finished."""
    call = Call.of(name, params, options, half=True)
    arr = state_rows(params, states, "states", call, "half")
    start = Columns(arr, call.spec("half").x)
    return call.batch("half", start, {}, arr.shape[:1], batch_result, given=start)
