"""The public map API, generic over every map of the index (``slipmaps.maps()``) and ``"exact"``.

- :func:`stance`: polar touchdown state ``(q_r, q_rd, q_th, q_thd)`` -> bottom and liftoff states,
  ``t_bottom``, ``t_stance`` (times from touchdown) and the map's extras.
- :func:`apex_return`: apex ``(height [m], speed [m/s])`` and touchdown leg angle [rad] -> the next
  apex (``apex_height``, ``apex_speed``), flight and stance times, liftoff state; the flights are
  exact (ballistic, ``g_f``), only the stance differs between maps.
- :func:`stance_batch`, :func:`apex_return_batch`: the same over arrays, in parallel for the
  generated maps and for ``"exact"`` (unless ``method="scipy"``); every row gets its own status,
  and a bad row (NaN, out of domain) gets ``INVALID_INPUT`` without failing the others.
  Apex-return inputs broadcast against each other.
- :func:`trajectory`: the polar state along the stance.
- :func:`half_stance`, :func:`half_stance_batch`: a half-stance map (``slipmaps maps`` lists them):
  the touchdown state -> ``t_half`` and the bottom state (compression, k_c), or a bottom state
  ``(q_r, q_rd, q_th, q_thd)`` (q_rd ignored: 0 at the bottom) -> ``t_half`` and the liftoff state
  (decompression, k_d); ``res.end`` is the end state. A controller picks k_d between the two calls.

Options are keywords (``iterations=20``, ``reading="mean"``; ``slipmaps maps`` lists them). A scalar
call raises ValueError for an invalid argument (naming it); a state outside the map's domain is a
result with a status, never an exception. Conventions (README): SI units, leg angle from the
vertical, counterclockwise positive.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from slipmaps.generated.status import MESSAGES, Status

from .index import MapInfo, get, get_half, maps
from .params import SlipParams
from .results import BatchResult, Result, columns
from .validate import L0_SLACK, float_array, leg_angle, non_negative, polar_state, real_array

__all__ = [
    "maps",
    "stance",
    "stance_batch",
    "apex_return",
    "apex_return_batch",
    "trajectory",
    "half_stance",
    "half_stance_batch",
]


@dataclass(frozen=True)
class _Call:
    """A map, its parameter values and its options, validated once per call."""

    info: MapInfo
    params: tuple[float, ...]
    options: dict  # the resolved options, by name
    encoded: tuple[float, ...]  # the kernel arguments of the options
    kernels: dict  # (role, batch) -> the generated function; empty for "exact"

    @classmethod
    def of(cls, name: str, params: SlipParams, options: dict, half: bool = False) -> _Call:
        """Validated once per (map, parameters, options): a control loop calling a map thousands of
        times with the same ones pays the Python checks once. ``half``: a half-stance map."""
        try:
            key = (name, params, tuple(sorted(options.items())), half)
            hash(key)
        except TypeError:  # an unhashable option value: validate (and refuse) it uncached
            return cls._build(name, params, options, half)
        return cls._cached(key)

    @staticmethod
    @lru_cache(maxsize=256)
    def _cached(key) -> _Call:
        name, params, options, half = key
        return _Call._build(name, params, dict(options), half)

    @classmethod
    def _build(cls, name: str, params: SlipParams, options: dict, half: bool = False) -> _Call:
        info = get_half(name) if half else get(name)
        prm = info.param_values(params)
        resolved = info.resolve(options)
        encoded = info.encode(resolved)  # ValueError naming the valid values
        kernels = {}
        if info.generated:
            module = info.kernel_module()
            for role, kernel in info.kernels.items():
                if kernel is not None:
                    kernels[(role, False)] = getattr(module, kernel)
                    kernels[(role, True)] = getattr(module, f"{kernel}_batch")
        return cls(info, prm, resolved, encoded, kernels)

    def kernel(self, role: str, batch: bool = False):
        return self.kernels[(role, batch)]

    def result(self, kind: str, res, inputs: dict) -> Result:
        status = Status(int(res[-1]))
        names = columns(kind, self.info.extras)
        values = dict(zip(names, map(float, res[:-1]), strict=True))
        return Result(self.info.name, kind, status, MESSAGES[int(status)], values, inputs)


def stance(name: str, params: SlipParams, touchdown, **options) -> Result:
    """One stance of map ``name`` from the polar touchdown state ``touchdown``."""
    call = _Call.of(name, params, options)
    td = polar_state(params, touchdown)
    inputs = {"touchdown": td, "options": dict(call.options)}
    if not call.info.generated:
        from ..exact import backend as exact_map  # loads scipy's integrators only when the exact map is used

        return exact_map.stance(params, td, inputs, **call.options)
    res = call.kernel("stance")(*td, *call.params, params.q_r_lo, *call.encoded)
    return call.result("stance", res, inputs)


def apex_return(name: str, params: SlipParams, apex_height, apex_speed, touchdown_angle, **options) -> Result:
    """One step of map ``name``: apex -> touchdown (leg at ``touchdown_angle``) -> stance -> next apex."""
    call = _Call.of(name, params, options)
    h = non_negative("apex_height", apex_height)
    v = non_negative("apex_speed", apex_speed)
    th = leg_angle("touchdown_angle", touchdown_angle)
    inputs = {"apex_height": h, "apex_speed": v, "touchdown_angle": th, "options": dict(call.options)}
    if not call.info.generated:
        from ..exact import backend as exact_map

        return exact_map.apex_return(params, h, v, th, inputs, **call.options)
    res = call.kernel("apex_return")(
        h, v, th, *call.params, params.g_f, params.q_r_td, params.q_r_lo, *call.encoded
    )
    return call.result("apex_return", res, inputs)


def _rows(params: SlipParams, touchdowns, what: str = "touchdowns") -> np.ndarray:
    """(n, 4) float64 touchdown (or bottom) states; leg lengths within round-off above l0 are l0, as in
    :func:`stance` (the only copy made: when such a row exists)."""
    arr = real_array(what, touchdowns)
    if arr.ndim != 2 or arr.shape[1] != 4:
        raise ValueError(f"{what} must have shape (n, 4) (q_r, q_rd, q_th, q_thd), got {arr.shape}")
    above = arr[:, 0] > params.l0
    if above.any():
        snap = above & (arr[:, 0] <= params.l0 * (1.0 + L0_SLACK))
        if snap.any():
            arr = arr.copy()
            arr[snap, 0] = params.l0
    return arr


def stance_batch(
    name: str, params: SlipParams, touchdowns, *, progress: bool | None = None, **options
) -> BatchResult:
    """Map ``name`` over touchdown states of shape (n, 4); a status per row."""
    call = _Call.of(name, params, options)
    arr = _rows(params, touchdowns)
    names = columns("stance", call.info.extras)
    n = arr.shape[0]
    if not call.info.generated:
        from ..exact import backend as exact_map

        data, status = exact_map.stance_rows(params, arr, names, progress, **call.options)
        return BatchResult(call.info.name, "stance", names, data, status, (n,))
    out = np.empty((n, len(names)))
    status = np.empty(n, dtype=np.int64)
    cols = (arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3])
    call.kernel("stance", batch=True)(*cols, *call.params, params.q_r_lo, *call.encoded, out, status)
    return BatchResult(call.info.name, "stance", names, out, status, (n,))


def _apex_rows(apex_height, apex_speed, touchdown_angle) -> tuple[tuple[np.ndarray, ...], tuple[int, ...]]:
    """The three apex-return inputs broadcast against each other, flattened (read-only views where
    possible: stride 0 for a broadcast scalar), and their broadcast shape."""
    given = {"apex_height": apex_height, "apex_speed": apex_speed, "touchdown_angle": touchdown_angle}
    parts = np.broadcast_arrays(*(real_array(key, x) for key, x in given.items()))
    shape = parts[0].shape
    n = int(np.prod(shape))
    flat = tuple(p.reshape(n) for p in parts)
    for p in flat:
        p.flags.writeable = False  # the kernels only read; numpy warns on writing through a broadcast
    return flat, shape


def apex_return_batch(
    name: str,
    params: SlipParams,
    apex_height,
    apex_speed,
    touchdown_angle,
    *,
    progress: bool | None = None,
    **options,
) -> BatchResult:
    """Map ``name`` over apexes and touchdown angles (arrays broadcast); a status per row.

    The result's columns have the broadcast shape of the three inputs.
    """
    call = _Call.of(name, params, options)
    flat, shape = _apex_rows(apex_height, apex_speed, touchdown_angle)
    n = int(np.prod(shape))
    names = columns("apex_return", call.info.extras)
    if not call.info.generated:
        from ..exact import backend as exact_map

        data, status = exact_map.apex_rows(params, flat, names, progress, **call.options)
        return BatchResult(call.info.name, "apex_return", names, data, status, shape)
    out = np.empty((n, len(names)))
    status = np.empty(n, dtype=np.int64)
    extra = (params.g_f, params.q_r_td, params.q_r_lo)
    call.kernel("apex_return", batch=True)(*flat, *call.params, *extra, *call.encoded, out, status)
    return BatchResult(call.info.name, "apex_return", names, out, status, shape)


def trajectory(
    name: str, params: SlipParams, touchdown, t=None, **options
) -> tuple[np.ndarray, np.ndarray, Status]:
    """The stance of map ``name`` from ``touchdown``: ``(t, states, status)``.

    ``states`` has shape (len(t), 4): q_r, q_rd, q_th, q_thd at the times ``t`` after touchdown.
    For the approximate maps ``t`` defaults to 200 points from touchdown to the map's liftoff; for
    ``"exact"`` the times are solve_ivp's steps and dense samples (``t`` must be None).
    """
    call = _Call.of(name, params, options)
    td = polar_state(params, touchdown)
    if not call.info.generated:
        if t is not None:
            raise ValueError("the exact trajectory is sampled at the integrator's times: call it with t=None")
        from ..exact import backend as exact_map

        return exact_map.trajectory(params, td, **call.options)
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
    out = np.empty((times.shape[0], 4))
    status = np.empty(times.shape[0], dtype=np.int64)
    call.kernel("state_at", batch=True)(times, *td, *call.params, params.q_r_lo, *call.encoded, out, status)
    bad = status[status != int(Status.OK)]
    return times, out, Status(int(bad[0])) if bad.size else Status.OK


def half_stance(name: str, params: SlipParams, state, **options) -> Result:
    """One half of the stance by half-stance map ``name`` from its start state (polar, SI): the
    touchdown state for a compression half, a bottom state for a decompression half."""
    call = _Call.of(name, params, options, half=True)
    start = polar_state(params, state, what=f"{call.info.start} state")
    res = call.kernel("half")(*start, *call.params, *call.encoded)
    return call.result("half", res, {call.info.start: start, "options": dict(call.options)})


def half_stance_batch(name: str, params: SlipParams, states, **options) -> BatchResult:
    """Half-stance map ``name`` over start states of shape (n, 4); a status per row."""
    call = _Call.of(name, params, options, half=True)
    arr = _rows(params, states, "states")
    names = columns("half", call.info.extras)
    n = arr.shape[0]
    out = np.empty((n, len(names)))
    status = np.empty(n, dtype=np.int64)
    cols = (arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3])
    call.kernel("half", batch=True)(*cols, *call.params, *call.encoded, out, status)
    return BatchResult(call.info.name, "half", names, out, status, (n,))
