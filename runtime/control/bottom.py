"""The second stage of a two-stage step: re-choose k_d at the bottom from the measured bottom state.

A step planned at the apex (:mod:`.deadbeat`) predicts its whole stance with the model map, the
compression half included. At the bottom (q_rd = 0) the controller can measure the state and
choose k_d again, now with only the decompression half's model error: :class:`BottomDeadbeat`
solves next apex = target for k_d with a decompression half map (``slipmaps maps`` lists them:
``iterative-decompression``, ``exact-decompression``, ...) from the bottom state, then the exact
flight from liftoff (in the direction the body moves at liftoff).

One control and the targets: the height and the speed by least squares (scaled as the apex stage
scales them: height / l0, speed / sqrt(g_f l0); ``aim="both"``, the default), or one of them
(``aim="height"``, ``aim="speed"``). k_d moves the energy only (by (k_d - k_c)(l0 - q_r_b)^2 / 2),
so with both targets the next apex is generally not reached exactly: the closest in the scaled norm,
status UNREACHABLE with its residual, is the normal outcome unless the apex stage's plan was right.

The same compiled solver as the apex stage (:func:`~.compiled.bottom_kernels_for`); the half maps
have no Jacobian kernel, so d/d k_d is a central difference (relative step
:data:`~.compiled.FD_STEP`). Bounds of k_d as the apex stage's (default [0.5, 2] x params.k_c).
"""

from __future__ import annotations

import math

import numpy as np

from ..api.calls import KERNELS, Call
from ..api.numeric import num
from ..api.params import SlipParams
from ..api.validate import check_params, polar_state, real
from . import compiled
from .compiled import BOTTOM_OUTPUTS, N_FLOATS, N_HEAD, N_INTS
from .deadbeat import DEFAULT_STIFFNESS_RANGE, MAX_EVALUATIONS, SCAN, TOL, SolveStatus

__all__ = ["AIMS", "BottomDeadbeat", "BottomResult"]

#: What the bottom stage aims at: both components (least squares), or one.
AIMS = {"both": (1, 1), "height": (1, 0), "speed": (0, 1)}


class BottomResult(SolveStatus):
    """One bottom-stage solve: ``status`` (:class:`~.deadbeat.PlanStatus`), ``k_d``, the predicted
    next apex ``apex_height`` / ``apex_speed``, ``residual`` (scaled), ``map_status``, ``t_half``,
    ``t_ascent``, ``liftoff`` (the polar state), ``evaluations``; ``reached``, ``ok`` as a
    :class:`~.deadbeat.DeadbeatResult`'s."""

    __slots__ = ("_out", "half", "targets")

    def __init__(self, half: str, out: np.ndarray, targets):
        self._out, self.half, self.targets = out, half, targets

    @property
    def k_d(self) -> float:
        return float(self._out[5])

    @property
    def residual(self) -> float:
        return float(self._out[8])

    @property
    def evaluations(self) -> int:
        return int(self._out[2]) * 3 + int(self._out[3])

    def _value(self, name: str) -> float:
        return float(self._out[N_HEAD + BOTTOM_OUTPUTS.index(name)])

    @property
    def apex_height(self) -> float:
        return self._value("apex_height")

    @property
    def apex_speed(self) -> float:
        return self._value("apex_speed")

    @property
    def t_half(self) -> float:
        return self._value("t_half")

    @property
    def t_ascent(self) -> float:
        return self._value("t_ascent")

    @property
    def liftoff(self) -> tuple[float, float, float, float]:
        j = N_HEAD + BOTTOM_OUTPUTS.index("liftoff_q_r")
        return tuple(float(x) for x in self._out[j : j + 4])

    def __repr__(self) -> str:
        return (
            f"BottomResult(half={self.half!r}, status={self.status.value}, k_d={self.k_d!r}, "
            f"apex_height={self.apex_height!r}, apex_speed={self.apex_speed!r}, residual={self.residual:.3g})"
        )


class BottomDeadbeat:
    """k_d at the bottom by decompression half map ``half`` (module docstring), prepared once."""

    def __init__(
        self,
        half: str,
        params: SlipParams,
        *,
        bounds=None,
        aim: str = "both",
        tol: float = TOL,
        scan: int = SCAN,
        **options,
    ):
        check_params(params)
        call = Call.of(half, params, options, half=True)
        if call.info.start != "bottom":
            raise ValueError(
                f"half map {call.info.name!r} runs {call.info.start} -> {call.info.end}; the bottom stage "
                "needs a decompression half (bottom -> liftoff)"
            )
        if call.backend is not KERNELS:
            raise ValueError(f"half map {call.info.name!r} runs outside the compiled kernels")
        if aim not in AIMS:
            raise ValueError(f"aim must be one of {', '.join(AIMS)}, got {aim!r}")
        lo, hi = (f * params.k_c for f in DEFAULT_STIFFNESS_RANGE) if bounds is None else bounds
        lo, hi = real("bounds low", lo), real("bounds high", hi)
        if not 0.0 < lo < hi:
            raise ValueError(f"k_d bounds must satisfy 0 < low < high, got ({num(lo)}, {num(hi)})")
        self.name = call.info.name
        self.params = params
        self.call = call
        self.bounds = (lo, hi)
        self.aim = aim
        spec = call.spec("half")
        self.args = spec.args
        self._kernels = compiled.bottom_kernels_for(call)
        n = len(spec.args)
        # a row: the half's arguments, g_f, then the target height and speed
        self._template = np.array(
            [float(call.values.get(a, math.nan)) for a in spec.args] + [params.g_f, 0, 0]
        )
        self._state = [spec.args.index(a) for a in spec.rows]
        self._i_kd = spec.args.index("k_d")
        fi, ff = compiled.INT_FIELDS, compiled.FLOAT_FIELDS
        ints = np.zeros(N_INTS, dtype=np.int64)
        floats = np.zeros(N_FLOATS)
        ints[fi["n_out"]], ints[fi["n_wrt"]] = len(BOTTOM_OUTPUTS), 1
        ints[fi["out_height"]], ints[fi["out_speed"]] = 0, 1
        ints[fi["n_controls"]], ints[fi["arg"]], ints[fi["col"]] = 1, self._i_kd, 0
        ints[fi["kd_col"]] = 0
        ints[fi["max_evaluations"]] = MAX_EVALUATIONS
        ints[fi["broyden"]] = 1
        ints[fi["scan"]] = scan
        ints[fi["targeted"]], ints[fi["targeted"] + 1] = AIMS[aim]
        ints[fi["n_args"]] = n + 1
        ints[fi["kd_arg"]] = self._i_kd
        floats[ff["lo"]], floats[ff["hi"]], floats[ff["scale"]] = lo, hi, params.k_c
        floats[ff["weight"]] = 1.0 / params.l0
        floats[ff["weight"] + 1] = 1.0 / math.sqrt(params.g_f * params.l0)
        floats[ff["tol"]] = real("tol", tol)
        floats[ff["m"]], floats[ff["g_f"]] = params.m, params.g_f
        floats[ff["kd_lo"]], floats[ff["kd_hi"]] = lo, hi
        self._ints, self._floats = ints, floats

    def warm(self, batch: bool = False) -> BottomDeadbeat:
        """Compile the solver now (``batch``: the parallel form too); returns self."""
        p = self.params
        state = (0.9 * p.l0, 0.0, 0.0, -math.sqrt(p.g_f / p.l0))
        v = math.sqrt(p.g_f * p.l0)
        self.plan(state, p.l0, v)
        if batch:
            self.plan_batch(np.array([state]), p.l0, v)
        return self

    def _targets(self, target_height, target_speed) -> tuple[float, float]:
        th, tv = AIMS[self.aim]
        H = real("target_height", target_height) if th else math.nan
        V = real("target_speed", target_speed) if tv else math.nan
        return H, V

    def plan(self, bottom, target_height, target_speed, *, k_d=None) -> BottomResult:
        """k_d from the bottom state (q_r, q_rd, q_th, q_thd; q_rd is 0 at a bottom) for the target;
        ``k_d`` the starting value (default the parameters' k_d)."""
        state = polar_state(self.params, bottom, what="bottom")
        H, V = self._targets(target_height, target_speed)
        a = self._template.copy()
        for i, x in zip(self._state, state, strict=True):
            a[i] = x
        if k_d is not None:
            a[self._i_kd] = real("k_d", k_d)
        a[self._i_kd] = min(max(a[self._i_kd], self.bounds[0]), self.bounds[1])
        a[-2] = 0.0 if math.isnan(H) else H
        a[-1] = 0.0 if math.isnan(V) else V
        out = np.empty(self._kernels.width)
        self._kernels.scalar(a, self._ints, self._floats, out)
        return BottomResult(self.name, out, (H, V))

    def plan_batch(self, bottoms, target_height, target_speed, *, k_d=None) -> dict[str, np.ndarray]:
        """:meth:`plan` over bottom states of shape (n, 4) in parallel (targets and starting k_d
        broadcast to n): columns ``status`` (plan codes), ``map_status``, ``k_d``, ``residual`` and
        the model's outputs (``apex_height``, ``apex_speed``, ``t_half``, ``t_ascent``, ``liftoff_*``)."""
        B = np.asarray(bottoms, dtype=float)
        if B.ndim != 2 or B.shape[1] != 4:
            raise ValueError(f"bottoms must have shape (n, 4), got {B.shape}")
        n = B.shape[0]
        th, tv = AIMS[self.aim]
        A = np.tile(self._template, (n, 1))
        for j, i in enumerate(self._state):
            A[:, i] = B[:, j]
        if k_d is not None:
            A[:, self._i_kd] = np.broadcast_to(np.asarray(k_d, dtype=float), (n,))
        A[:, self._i_kd] = np.clip(A[:, self._i_kd], *self.bounds)
        A[:, -2] = np.broadcast_to(np.asarray(target_height if th else 0.0, dtype=float), (n,))
        A[:, -1] = np.broadcast_to(np.asarray(target_speed if tv else 0.0, dtype=float), (n,))
        OUT = np.empty((n, self._kernels.width))
        if n:
            self._kernels.batch(A, self._ints, self._floats, OUT)
        cols = {"status": OUT[:, 0].astype(np.int64), "map_status": OUT[:, 1].astype(np.int64)}
        cols["k_d"] = OUT[:, 5]
        cols["residual"] = OUT[:, 8]
        for j, name in enumerate(BOTTOM_OUTPUTS):
            cols[name] = OUT[:, N_HEAD + j]
        return cols
