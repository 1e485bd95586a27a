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

The same compiled solver as the apex stage (:class:`~.compiled.Solver`) on the half map's ``apex``
role (the half, then the flight; derive/halfspec.py); the half maps have no Jacobian kernel, so
d/d k_d is a central difference (relative step :data:`FD_STEP`). Bounds of k_d as the apex stage's
(default [0.5, 2] x params.k_c).
"""

from __future__ import annotations

import math

import numpy as np

from ..api.calls import KERNELS, Call
from ..api.names import RENAMED, Renamed, RenamedKeys, public_names
from ..api.numeric import num
from ..api.params import SlipParams
from ..api.validate import check_params, polar_state, real
from . import compiled
from .compiled import HEAD_AT as _HEAD
from .compiled import N_HEAD
from .deadbeat import DEFAULT_STIFFNESS_RANGE, MAX_EVALUATIONS, SCAN, TOL, SolveStatus

__all__ = ["AIMS", "FD_STEP", "BottomDeadbeat", "BottomResult"]

#: Relative step of the central difference in k_d (the half maps have no Jacobian kernel).
FD_STEP = 1e-5

#: What the bottom stage aims at: both components (least squares), or one.
AIMS = {"both": (1, 1), "height": (1, 0), "speed": (0, 1)}


class BottomResult(SolveStatus):
    """One bottom-stage solve: ``status`` (:class:`~.deadbeat.PlanStatus`), ``k_d``, the predicted
    next apex ``next_apex_height`` / ``next_apex_speed`` (the former names ``apex_height`` /
    ``apex_speed`` still read, with a DeprecationWarning), ``residual`` (scaled), ``map_status``, ``t_half``,
    ``t_ascent``, ``liftoff`` (the polar state), ``evaluations``; ``reached``, ``ok`` as a
    :class:`~.deadbeat.DeadbeatResult`'s."""

    __slots__ = ("_out", "half", "targets", "_outputs")

    def __init__(self, half: str, out: np.ndarray, targets, outputs: tuple[str, ...]):
        self._out, self.half, self.targets, self._outputs = out, half, targets, outputs

    @property
    def k_d(self) -> float:
        return float(self._out[_HEAD["u0"]])

    @property
    def residual(self) -> float:
        return float(self._head("residual"))

    @property
    def evaluations(self) -> int:
        return int(self._head("jacobians")) * 3 + int(self._head("evaluations"))

    def _value(self, name: str) -> float:
        return float(self._out[N_HEAD + self._outputs.index(name)])

    @property
    def next_apex_height(self) -> float:
        return self._value("apex_height")

    @property
    def next_apex_speed(self) -> float:
        return self._value("apex_speed")

    apex_height = Renamed("next_apex_height", "a bottom-stage result")
    apex_speed = Renamed("next_apex_speed", "a bottom-stage result")

    @property
    def t_half(self) -> float:
        return self._value("t_half")

    @property
    def t_ascent(self) -> float:
        return self._value("t_ascent")

    @property
    def liftoff(self) -> tuple[float, float, float, float]:
        j = N_HEAD + self._outputs.index("liftoff_q_r")
        return tuple(float(x) for x in self._out[j : j + 4])

    def __repr__(self) -> str:
        return (
            f"BottomResult(half={self.half!r}, status={self.status.value}, k_d={self.k_d!r}, "
            f"next_apex_height={self.next_apex_height!r}, next_apex_speed={self.next_apex_speed!r}, "
            f"residual={self.residual:.3g})"
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
        spec = call.spec("apex")
        self.solver = compiled.Solver(spec)
        self.outputs = spec.outputs
        self._state = [spec.x.index(a) for a in call.spec("half").x]
        self._record = call.record(spec)
        self._i_kd = spec.p.index("k_d")
        self._settings = self.solver.settings(
            ["k_d"],
            [lo],
            [hi],
            [params.k_c],
            targeted=AIMS[aim],
            fd_step=FD_STEP,
            kd="k_d",
            kd_bounds=(lo, hi),
            weight=[1.0 / params.l0, 1.0 / math.sqrt(params.g_f * params.l0)],
            tol=real("tol", tol),
            mass=params.m,
            g_f=params.g_f,
            max_evaluations=MAX_EVALUATIONS,
            broyden=1,
            scan=scan,
        )

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

    def _records(self, k_d, n: int) -> np.ndarray:
        """The parameter records: the half's, with the starting k_d (one for all rows, or one per
        row), clipped into the bounds."""
        P = self._record[None, :].copy()
        if k_d is not None:
            kd = np.asarray(k_d, dtype=float)
            if kd.ndim:
                P = np.repeat(P, n, axis=0)
                P[:, self._i_kd] = np.broadcast_to(kd, (n,))
            else:
                P[:, self._i_kd] = real("k_d", float(kd))
        P[:, self._i_kd] = np.clip(P[:, self._i_kd], *self.bounds)
        return P

    def plan(self, bottom, target_height, target_speed, *, k_d=None) -> BottomResult:
        """k_d from the bottom state (q_r, q_rd, q_th, q_thd; q_rd is 0 at a bottom) for the target;
        ``k_d`` the starting value (default the parameters' k_d)."""
        state = polar_state(self.params, bottom, what="bottom")
        H, V = self._targets(target_height, target_speed)
        X = np.empty((1, len(self.solver.x)))
        X[0, self._state] = state
        T = np.array([[0.0 if math.isnan(H) else H, 0.0 if math.isnan(V) else V]])
        out = self.solver.run(X, self._records(k_d, 1), T, self._settings)[0]
        return BottomResult(self.name, out, (H, V), self.outputs)

    def plan_batch(self, bottoms, target_height, target_speed, *, k_d=None) -> dict[str, np.ndarray]:
        """:meth:`plan` over bottom states of shape (n, 4) in parallel (targets and starting k_d
        broadcast to n): columns ``status`` (plan codes), ``map_status``, ``k_d``, ``residual`` and
        the model's outputs (``next_apex_height``, ``next_apex_speed``, ``t_half``, ``t_ascent``,
        ``liftoff_*``; the former names of the next apex still read, with a DeprecationWarning)."""
        B = np.asarray(bottoms, dtype=float)
        if B.ndim != 2 or B.shape[1] != 4:
            raise ValueError(f"bottoms must have shape (n, 4), got {B.shape}")
        n = B.shape[0]
        th, tv = AIMS[self.aim]
        X = np.empty((n, len(self.solver.x)))
        X[:, self._state] = B
        T = np.empty((n, 2))
        T[:, 0] = np.broadcast_to(np.asarray(target_height if th else 0.0, dtype=float), (n,))
        T[:, 1] = np.broadcast_to(np.asarray(target_speed if tv else 0.0, dtype=float), (n,))
        OUT = self.solver.run(X, self._records(k_d, n), T, self._settings)
        cols = {
            "status": OUT[:, _HEAD["plan_status"]].astype(np.int64),
            "map_status": OUT[:, _HEAD["map_status"]].astype(np.int64),
            "k_d": OUT[:, _HEAD["u0"]],
            "residual": OUT[:, _HEAD["residual"]],
        }
        for j, name in enumerate(public_names(self.outputs)):
            cols[name] = OUT[:, N_HEAD + j]
        return RenamedKeys(cols, RENAMED, "a bottom-stage batch")
