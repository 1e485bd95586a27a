"""The plant of a run: one step of a map (the exact simulator by default) with the stiffness the
controller commands, over many runs at once.

A step of the plant is the composition every apex-return map is (the generated ``exact`` step's,
``generated/exact.py``): the exact ballistic descent (``flight.apex_to_touchdown``), the map's stance
(its generated stance kernel) with the step's k_c and k_d, the exact ascent to the next apex
(:func:`~.compiled.ascent`). One difference, on purpose: the ascent flies in the direction the body
moves at liftoff, so a stance that reverses the direction (a turn from a hop in place, the slight
overshoot of a stop) continues as the body does, where ``slipmaps.apex_return`` reports
LIFTOFF_BACKWARD (a model convention: a step keeps its direction). Otherwise a plant step equals
``slipmaps.apex_return`` of the same map bitwise (tests/test_control_runs.py).

Every quantity is per row (a run of a batch): apex, touchdown angle, ground, k_c and k_d, so one
call steps every run of an evaluation in parallel. The two-stage form splits the stance at the
bottom: :meth:`Plant.compress` (the plant's compression half, touchdown -> bottom, k_c), then
:meth:`Plant.decompress` (its decompression half, bottom -> liftoff, with the k_d the controller
chose there) and the ascent; it needs a plant map with half maps (``exact``, ``iterative``,
``iterative-report``).

A constant-stiffness plant (``geyer``, the gravity corrections) takes k = k_c and refuses a row
whose k_d differs (INVALID_INPUT).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from slipmaps.generated.flight import apex_to_touchdown
from slipmaps.generated.status import Status

from ..api.calls import KERNELS, Call
from ..api.index import halves
from ..api.params import SlipParams
from .compiled import ascent, in_threads

__all__ = ["Plant", "PlantSteps", "row_caller"]

_ROWS: dict = {}


def row_caller(fn, n_args: int, n_ret: int):
    """A loop calling the scalar njit function ``fn`` on each row of A (n, n_args), its n_ret return
    values written into D (n, n_ret) (a status returned as a float); compiled once per function,
    releasing the GIL (:func:`_call` runs it in threads)."""
    key = (fn, n_args, n_ret)
    hit = _ROWS.get(key)
    if hit is not None:
        return hit
    args = ", ".join(f"A[i, {j}]" for j in range(n_args))
    stores = "\n".join(f"        D[i, {j}] = r[{j}]" for j in range(n_ret))
    source = f"def rows(A, D):\n    for i in range(A.shape[0]):\n        r = F({args})\n{stores}\n"
    ns = {"F": fn}
    exec(source, ns)  # the source is built here, from the kernel's arity
    caller = njit(error_model="numpy", nogil=True)(ns["rows"])
    _ROWS[key] = caller
    return caller


def _call(fn, n_ret: int, columns: list[np.ndarray]) -> np.ndarray:
    A = np.ascontiguousarray(np.stack(columns, axis=1), dtype=np.float64)
    D = np.empty((A.shape[0], n_ret))
    if A.shape[0]:
        in_threads(row_caller(fn, A.shape[1], n_ret), A, D)
    return D


@dataclass
class PlantSteps:
    """One step of many runs (arrays of n rows; NaN where the row's ``status`` is not OK):
    ``touchdown``, ``bottom``, ``liftoff`` (n, 4) polar states, times ``t_descent``, ``t_bottom``,
    ``t_stance``, ``t_ascent`` [s], ``foot_x`` (the foot at touchdown relative to the apex),
    ``step_length`` (apex to apex), the next apex ``apex_height`` (above the touchdown ground),
    ``apex_speed``, and the stiffness the plant ran with, ``k_c`` and ``k_d``."""

    status: np.ndarray
    touchdown: np.ndarray
    t_descent: np.ndarray
    foot_x: np.ndarray
    t_bottom: np.ndarray
    bottom: np.ndarray
    t_stance: np.ndarray
    liftoff: np.ndarray
    t_ascent: np.ndarray
    apex_height: np.ndarray
    apex_speed: np.ndarray
    step_length: np.ndarray
    k_c: np.ndarray
    k_d: np.ndarray

    @property
    def ok(self) -> np.ndarray:
        return self.status == int(Status.OK)


class Plant:
    """Map ``name`` as a plant with parameters ``params`` (the true ones: a model mismatch is a
    plant whose mass or stiffness differs from the controller's) and the map's options."""

    def __init__(self, name: str, params: SlipParams, **options):
        call = Call.of(name, params.with_(k=params.k_c), options)
        if call.backend is not KERNELS:
            raise ValueError(f"map {call.info.name!r} with these options runs outside the compiled kernels")
        self.name = call.info.name
        self.params = params
        self.options = dict(call.options)
        self.call = call
        spec = call.spec("stance")
        self._stance = spec
        self._constant = "k" in spec.args
        self._lo = [spec.outputs.index(f"liftoff_{q}") for q in ("q_r", "q_rd", "q_th", "q_thd")]
        self._bo = [spec.outputs.index(f"bottom_{q}") for q in ("q_r", "q_rd", "q_th", "q_thd")]
        self._halves = {h.start: h.name for h in halves() if h.whole == self.name}

    @property
    def has_halves(self) -> bool:
        return {"touchdown", "bottom"} <= set(self._halves)

    # ------------------------------------------------------------------------------------------
    def _descent(self, h, v, th, ground):
        p = self.params
        n = h.shape[0]
        D = _call(apex_to_touchdown, 7, [h, v, th, np.full(n, p.q_r_td), np.full(n, p.g_f), ground])
        return D[:, 6].astype(np.int64), D[:, 0:4], D[:, 4], D[:, 5]

    def _args(self, spec, values: dict, n: int) -> list[np.ndarray]:
        base = {**self.call.values, **self.params.values()}
        cols = []
        for a in spec.args:
            cols.append(values[a] if a in values else np.full(n, float(base[a])))
        return cols

    def _stiffness(self, k_c, k_d, status) -> dict:
        if self._constant:
            bad = (k_c != k_d) & (status == 0)
            status[bad] = int(Status.INVALID_INPUT)
            return {"k": k_c}
        return {"k_c": k_c, "k_d": k_d}

    def _ascent(self, lo, status, foot_x):
        n = lo.shape[0]
        D = _call(ascent, 6, [lo[:, 0], lo[:, 1], lo[:, 2], lo[:, 3], np.full(n, self.params.g_f)])
        code = D[:, 5].astype(np.int64)
        status[(status == 0) & (code != 0)] = code[(status == 0) & (code != 0)]
        return D[:, 0], D[:, 1], D[:, 2], foot_x + D[:, 4]

    def step(self, apex_height, apex_speed, touchdown_angle, ground, k_c, k_d) -> PlantSteps:
        """One step of every row (module docstring)."""
        h, v, th, gr, kc, kd = (
            np.ascontiguousarray(np.atleast_1d(np.asarray(x, dtype=float)))
            for x in np.broadcast_arrays(apex_height, apex_speed, touchdown_angle, ground, k_c, k_d)
        )
        n = h.shape[0]
        status, td, t_descent, foot_x = self._descent(h, v, th, gr)
        values = {a: td[:, j] for j, a in enumerate(self._stance.rows)}
        values.update(self._stiffness(kc, kd, status))
        S = _call(
            self._stance.functions()[0], len(self._stance.outputs) + 1, self._args(self._stance, values, n)
        )
        code = S[:, -1].astype(np.int64)
        fresh = (status == 0) & (code != 0)
        status[fresh] = code[fresh]
        lo = S[:, self._lo]
        bottom = S[:, self._bo]
        lo[status != 0] = math.nan
        t_bottom = S[:, self._stance.outputs.index("t_bottom")]
        t_stance = S[:, self._stance.outputs.index("t_stance")]
        return self._finish(status, td, t_descent, foot_x, t_bottom, bottom, t_stance, lo, kc, kd)

    def _finish(self, status, td, t_descent, foot_x, t_bottom, bottom, t_stance, lo, kc, kd) -> PlantSteps:
        """The ascent from liftoff ``lo`` and the steps' record (NaN in the rows that failed)."""
        apex_h, apex_v, t_ascent, step_length = self._ascent(lo, status, foot_x)
        out = PlantSteps(
            status=status,
            touchdown=td,
            t_descent=t_descent,
            foot_x=foot_x,
            t_bottom=t_bottom,
            bottom=bottom,
            t_stance=t_stance,
            liftoff=lo,
            t_ascent=t_ascent,
            apex_height=apex_h,
            apex_speed=apex_v,
            step_length=step_length,
            k_c=kc,
            k_d=kd,
        )
        return _blank(out)

    # ------------------------------------------------------------------------------------------
    def _half(self, start: str):
        if not self.has_halves:
            have = sorted({h.whole for h in halves()})
            raise ValueError(
                f"a two-stage step needs the plant's half maps; map {self.name!r} has none (maps with "
                f"halves: {', '.join(have)})"
            )
        call = Call.of(self._halves[start], self.params, dict(self._half_options(start)), half=True)
        return call, call.spec("half")

    def _half_options(self, start: str) -> dict:
        """The plant's options that its half map also has (e.g. the exact map's rtol, atol)."""
        info = Call.of(self._halves[start], self.params, {}, half=True).info
        names = {o.name for o in info.options}
        return {k: v for k, v in self.options.items() if k in names}

    def compress(self, apex_height, apex_speed, touchdown_angle, ground, k_c):
        """The first stage of a two-stage step: the descent and the compression half (k_c):
        ``(status, touchdown, t_descent, foot_x, t_bottom, bottom)`` per row."""
        h, v, th, gr, kc = (
            np.ascontiguousarray(np.atleast_1d(np.asarray(x, dtype=float)))
            for x in np.broadcast_arrays(apex_height, apex_speed, touchdown_angle, ground, k_c)
        )
        status, td, t_descent, foot_x = self._descent(h, v, th, gr)
        bottom, t_half = self._run_half("touchdown", td, "k_c", kc, status)
        return status, td, t_descent, foot_x, t_half, bottom

    def _run_half(self, start: str, rows: np.ndarray, key: str, stiffness: np.ndarray, status: np.ndarray):
        """The half map from ``start`` on the polar ``rows`` with its stiffness ``key``: its end
        state (NaN where a row failed) and its duration; a fresh failure's code into ``status``."""
        call, spec = self._half(start)
        n = status.shape[0]
        values = {a: rows[:, j] for j, a in enumerate(spec.rows)} | {key: stiffness}
        base = {**call.values, **self.params.values()}
        cols = [values[a] if a in values else np.full(n, float(base[a])) for a in spec.args]
        D = _call(spec.functions()[0], len(spec.outputs) + 1, cols)
        code = D[:, -1].astype(np.int64)
        fresh = (status == 0) & (code != 0)
        status[fresh] = code[fresh]
        end = D[:, [spec.outputs.index(f"end_{q}") for q in ("q_r", "q_rd", "q_th", "q_thd")]]
        end[status != 0] = math.nan
        return end, D[:, spec.outputs.index("t_half")]

    def decompress(self, first, k_c, k_d) -> PlantSteps:
        """The second stage: from :meth:`compress`'s result ``first`` the decompression half with
        k_d, then the ascent."""
        status, td, t_descent, foot_x, t_bottom, bottom = (np.array(x, copy=True) for x in first)
        kc = np.broadcast_to(np.asarray(k_c, dtype=float), status.shape).copy()
        kd = np.broadcast_to(np.asarray(k_d, dtype=float), status.shape).copy()
        rows = np.where(np.isfinite(bottom), bottom, 0.0)
        rows[:, 0] = np.where(status == 0, rows[:, 0], self.params.l0 * 0.9)
        lo, t_half = self._run_half("bottom", rows, "k_d", kd, status)
        return self._finish(status, td, t_descent, foot_x, t_bottom, bottom, t_bottom + t_half, lo, kc, kd)


def _blank(out: PlantSteps) -> PlantSteps:
    """NaN in every value of a row that failed (never a silent number from a failed step)."""
    bad = out.status != 0
    if bad.any():
        for name in ("t_descent", "foot_x", "t_bottom", "t_stance", "t_ascent", "apex_height", "apex_speed"):
            getattr(out, name)[bad] = math.nan
        out.step_length[bad] = math.nan
        for name in ("touchdown", "bottom", "liftoff"):
            getattr(out, name)[bad] = math.nan
    return out
