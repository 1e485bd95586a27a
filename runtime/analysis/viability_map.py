"""The transition map of a viability study: every (state, action) pair of a grid stepped once.

A state is an apex: its height h [m] and forward speed v [m/s] (free energy), or its height alone at
a fixed flight energy E = m (g_f h + v^2/2) [J], v = sqrt(2 (E/m - g_f h)). An action is a touchdown
angle [rad], optionally the decompression stiffness k_d [N/m] and a swing-leg retraction rate
[rad/s]. The steps are calls of the public batch API (:func:`slipmaps.apex_return_batch`): one call
per k_d value (``params.with_(k_d=...)``, as the sweeps do per parameter set) and per chunk of
states, so the memory of a call stays bounded (:data:`CHUNK_ROWS` rows) whatever the grid.

A step fails (Heim and Spröwitz's failure set, vibly's SLIP model) when its status is not OK: the foot
would start underground (``APEX_TOO_LOW``, ``NO_TOUCHDOWN``), the body falls or the stance has no
flight after it (``FALL``, ``LIFTOFF_DOWNWARD``, ``LIFTOFF_BACKWARD``, ...), or any other failure of
the map (``NOT_CONVERGED`` of an approximate map counts as a fall too: it is no step); or when the
next apex speed is not positive (the runner no longer runs forward).

The next state at a fixed energy is vibly's: the next apex's share of potential energy
s' = g_f h' / (g_f h' + v'^2/2), as a height on the energy level, h' = s' E / (m g_f) (h' itself
whenever the step conserves the energy).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from slipmaps.generated.status import Status

from ..api import memory
from ..api.maps import apex_return_batch
from ..api.params import SlipParams
from ..api.progress import Bar

__all__ = ["CHUNK_ROWS", "Grids", "Transition", "check_memory", "speeds_on_energy", "steps", "transition"]

#: Rows (state-action pairs) per batch call: bounds the batch's output (~20 float64 columns).
CHUNK_ROWS = 2_000_000


@dataclass(frozen=True)
class Grids:
    """The grids of a viability study (1-D float64 arrays, ascending): ``states`` by name (``apex_height``
    and, with a free energy, ``apex_speed``), ``actions`` by name (``touchdown_angle``, then
    ``k_d`` and ``retraction_rate`` when given); ``energy`` [J] or None."""

    states: dict[str, np.ndarray]
    actions: dict[str, np.ndarray]
    energy: float | None

    @property
    def state_shape(self) -> tuple[int, ...]:
        return tuple(g.size for g in self.states.values())

    @property
    def action_shape(self) -> tuple[int, ...]:
        return tuple(g.size for g in self.actions.values())


@dataclass(frozen=True)
class Transition:
    """Every state-action pair stepped: ``failed`` (bool), ``status`` (int8 codes of
    :class:`~slipmaps.Status`; OK where only the speed failed) and ``next_state`` (float64, a
    trailing axis per state dimension, NaN where the step failed), in the shape states x actions;
    ``seconds`` the wall time of the steps."""

    failed: np.ndarray
    status: np.ndarray
    next_state: np.ndarray
    seconds: float


def check_memory(grids: Grids, available: int | None = None) -> int:
    """The bytes a study of ``grids`` holds (per pair: ``failed``, ``status``, ``viable`` and a
    temporary, 1 byte each, the cell index, 4, the next state, 8 per state dimension; and one batch
    call's chunk); ValueError (one line with the estimate) when it exceeds ``available`` (default:
    the machine's available memory: :func:`slipmaps.runtime.api.memory.check`)."""
    pairs = int(np.prod(grids.state_shape)) * int(np.prod(grids.action_shape))
    need = pairs * (8 + 8 * len(grids.states)) + CHUNK_ROWS * 8 * 24
    return memory.check(need, f"the grid's {pairs:,} state-action pairs need", "use coarser grids", available)


def speeds_on_energy(params: SlipParams, energy: float, heights: np.ndarray) -> np.ndarray:
    """The apex speeds v = sqrt(2 (E/m - g_f h)) of the heights on the energy level ``energy``."""
    return np.sqrt(np.maximum(2.0 * (energy / params.m - params.g_f * heights), 0.0))


def _chunks(n_states: int, per_state: int) -> list[slice]:
    """Slices of the states, each with at most :data:`CHUNK_ROWS` rows of ``per_state`` pairs per call."""
    size = max(1, CHUNK_ROWS // max(per_state, 1))
    return [slice(i, min(i + size, n_states)) for i in range(0, n_states, size)]


def steps(name, params, heights, speeds, angles, rates, energy, ground, options):
    """One batch call: apexes ``(heights[i], speeds[i])`` x ``angles`` (x ``rates``) by map ``name``
    with ``params``: ``(failed, status, next_state)`` of shape (n, angles[, rates]) (next_state with a
    trailing axis: (h', v'), or at a fixed ``energy`` the height on its level; NaN where failed)."""
    extra = (1,) * (1 + (rates is not None))
    h = np.asarray(heights, dtype=float).reshape(-1, *extra)
    v = np.asarray(speeds, dtype=float).reshape(-1, *extra)
    a = np.asarray(angles, dtype=float).reshape(1, -1, *([1] if rates is not None else []))
    kwargs = {} if rates is None else {"retraction_rate": np.asarray(rates, dtype=float).reshape(1, 1, -1)}
    res = apex_return_batch(name, params, h, v, a, ground=ground, progress=False, **kwargs, **options)
    code = res["status"]
    h1, v1 = res["next_apex_height"], res["next_apex_speed"]
    bad = (code != int(Status.OK)) | ~(v1 > 0.0)
    if energy is None:
        step = np.stack([h1, v1], axis=-1)
    else:
        g = params.g_f
        share = g * h1 / (g * h1 + 0.5 * v1 * v1)
        step = (share * energy / (params.m * g))[..., None]
    return bad, code, np.where(bad[..., None], math.nan, step)


def transition(
    name: str,
    params: SlipParams,
    grids: Grids,
    *,
    ground: float = 0.0,
    progress: bool | None = None,
    options: dict | None = None,
) -> Transition:
    """The transition map of ``grids`` by map ``name`` (module docstring)."""
    import time

    options = dict(options or {})
    heights = grids.states["apex_height"]
    free = "apex_speed" in grids.states
    angles = grids.actions["touchdown_angle"]
    stiffnesses = grids.actions.get("k_d")
    rates = grids.actions.get("retraction_rate")
    s_shape, a_shape = grids.state_shape, grids.action_shape
    d = len(s_shape)
    n_states = int(np.prod(s_shape))
    per_state = int(np.prod(a_shape))
    failed = np.ones(s_shape + a_shape, dtype=bool).reshape(n_states, *a_shape)
    status = np.full((n_states, *a_shape), int(Status.INVALID_INPUT), dtype=np.int8)
    nxt = np.full((n_states, *a_shape, d), math.nan)
    # the states as flat columns: (h, v) per state
    if free:
        hh, vv = np.meshgrid(heights, grids.states["apex_speed"], indexing="ij")
        h_all, v_all = hh.ravel(), vv.ravel()
    else:
        h_all, v_all = heights, speeds_on_energy(params, grids.energy, heights)
    calls = (
        [(None, params)]
        if stiffnesses is None
        else [(j, params.with_(k_d=float(k))) for j, k in enumerate(stiffnesses)]
    )
    chunks = _chunks(n_states, per_state // (1 if stiffnesses is None else stiffnesses.size))
    start = time.perf_counter()
    with Bar(len(calls) * n_states, f"viability: {name}", progress, unit="states") as bar:
        for j, p in calls:
            for rows in chunks:
                bad, code, step = steps(
                    name, p, h_all[rows], v_all[rows], angles, rates, grids.energy, ground, options
                )
                where = (rows,) if j is None else (rows, slice(None), j)
                failed[where] = bad
                status[where] = code
                nxt[where] = step
                bar.update(rows.stop - rows.start)
    seconds = time.perf_counter() - start
    shape = s_shape + a_shape
    return Transition(failed.reshape(shape), status.reshape(shape), nxt.reshape(*shape, d), seconds)
