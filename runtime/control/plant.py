"""The plant of a run: one step of a map (the exact simulator by default) with the stiffness the
controller commands, over many runs at once.

A step of the plant is the composition every apex-return map is (the generated ``exact`` step's,
``generated/exact.py``): the exact ballistic descent (the model kernel ``apex_to_touchdown``), the
map's stance (its role kernel, the step's k_c and k_d per row) and the exact ascent to the next apex
(``liftoff_to_apex``), every kernel called by name through the index
(:mod:`~slipmaps.runtime.api.model`, :mod:`~slipmaps.runtime.api.calls`). One difference, on
purpose: the ascent flies in the direction the body moves at liftoff, so a stance that reverses the
direction (a turn from a hop in place, the slight overshoot of a stop) continues as the body does,
where ``slipmaps.apex_return`` reports LIFTOFF_BACKWARD (a model convention: a step keeps its
direction). Otherwise a plant step equals ``slipmaps.apex_return`` of the same map bitwise
(tests/test_control_runs.py).

Every quantity is per row (a run of a batch): apex, touchdown angle, ground, k_c and k_d, so one
call steps every run of an evaluation in parallel. The two-stage form splits the stance at the
bottom: :meth:`Plant.compress` (the plant's compression half, touchdown -> bottom, k_c), then
:meth:`Plant.decompress` (its decompression half, bottom -> liftoff, with the k_d the controller
chose there) and the ascent; it needs a plant map with half maps (``exact``, ``iterative``,
``iterative-report``).

A constant-stiffness plant (``geyer``, the gravity corrections) takes k = k_c and refuses a row
whose k_d differs (INVALID_INPUT).

The plant interface (what :func:`~slipmaps.runtime.control.runs.run_batch` calls; :class:`Plant`
implements it for every map, ``slipmaps.runtime.control.robot_plant.RobotPlant`` for the
MuJoCo robot; ``slipmaps.runtime.control.runs.make_plant`` picks the scenario's):
``start(scenario, grounds, seeds)`` once before a batch's first step (a map plant has nothing to set
up; a robot places one robot per run on its terrain), ``step``, ``compress`` and ``decompress``
with the rows' run indices ``rows`` (a map plant is stateless and ignores them; a robot steps those
runs' robots, which keep their own state between steps), ``has_halves`` (two-stage steps),
``columns`` (the names of the plant's own per-step records in :attr:`PlantSteps.extras`: none for a
map). The swing leg is commanded either as an angle at the apex held (or retracting at
``retraction_rate``) or, with ``swing=``, as a time-based policy's tables
(:class:`~.swing.PolicyTables`: the angle and the stiffness as functions of the time since the
apex); a map plant reads the tables where the leg meets the ground (the touchdown is exact), a
robot's hip servo follows them. :attr:`PlantSteps.ground` is the ground the foot met, relative to
the ground under the apex: the commanded one for a map, the terrain's under the foot for a robot.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from slipmaps.generated.status import Status

from ..api import model
from ..api.calls import KERNELS, Call
from ..api.index import halves
from ..api.params import SlipParams

__all__ = ["Compressed", "Plant", "PlantSteps", "ROBOT", "ascent", "blank_failed"]

#: The plant that is not a map: the MuJoCo monoped (``slipmaps.runtime.robot``; the extra ``robot``).
ROBOT = "mujoco"

_POLAR = ("q_r", "q_rd", "q_th", "q_thd")


def ascent(liftoff: np.ndarray, g_f: float):
    """The exact flight from liftoff states (n, 4) to the next apex, in the direction the body moves
    at liftoff (a stance that reverses the direction, a turn from a hop in place or the slight
    overshoot of a stop, flies on as the body does): ``(status, outputs by name)`` of the model
    kernel ``liftoff_to_apex``."""
    q_r, q_rd, q_th, q_thd = liftoff.T
    b_xd = -np.sin(q_th) * q_rd - q_r * np.cos(q_th) * q_thd
    return model.rows(
        "liftoff_to_apex", q_r=q_r, q_rd=q_rd, q_th=q_th, q_thd=q_thd, g_f=g_f, direction=np.sign(b_xd)
    )


@dataclass
class PlantSteps:
    """One step of many runs (arrays of n rows; NaN where the row's ``status`` is not OK):
    ``touchdown``, ``bottom``, ``liftoff`` (n, 4) polar states, times ``t_descent``, ``t_bottom``,
    ``t_stance``, ``t_ascent`` [s], ``foot_x`` (the foot at touchdown relative to the apex),
    ``step_length`` (apex to apex), the next apex ``apex_height`` (above the touchdown ground),
    ``apex_speed``, the stiffness the plant ran with, ``k_c`` and ``k_d``, the ``ground`` the foot
    met (relative to the ground under the apex) and ``extras``, the plant's own records by name
    (:attr:`Plant.columns`; empty for a map)."""

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
    ground: np.ndarray
    extras: dict = field(default_factory=dict)

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
        self._constant = "k" in spec.p
        self._lo = [spec.outputs.index(f"liftoff_{q}") for q in _POLAR]
        self._bo = [spec.outputs.index(f"bottom_{q}") for q in _POLAR]
        self._halves = {h.start: h.name for h in halves() if h.whole == self.name}

    #: The plant's own per-step records (:attr:`PlantSteps.extras`): none for a map.
    columns: tuple[str, ...] = ()

    @property
    def has_halves(self) -> bool:
        return {"touchdown", "bottom"} <= set(self._halves)

    def start(self, scenario, grounds, seeds) -> None:
        """Before a batch's first step (module docstring): a map plant is stateless, nothing to do."""

    # ------------------------------------------------------------------------------------------
    def _descent(self, h, v, th, ground, rate):
        p = self.params
        code, out = model.rows(
            "apex_to_touchdown",
            b_y_apex=h,
            b_xd_apex=v,
            q_th_td=th,
            q_r_td=p.q_r_td,
            g_f=p.g_f,
            ground=ground,
            retraction_rate=rate,
        )
        td = np.stack([out[f"touchdown_{q}"] for q in _POLAR], axis=1)
        return code, td, out["t_flight"], out["foot_x"]

    def _stiffness(self, k_c, k_d, status) -> dict:
        if self._constant:
            bad = (k_c != k_d) & (status == 0)
            status[bad] = int(Status.INVALID_INPUT)
            return {"k": k_c}
        return {"k_c": k_c, "k_d": k_d}

    def _ascent(self, lo, status, foot_x):
        code, out = ascent(lo, self.params.g_f)
        fresh = (status == 0) & (code != 0)
        status[fresh] = code[fresh]
        return out["apex_b_y"], out["apex_b_xd"], out["t_flight"], foot_x + out["apex_b_x"]

    @staticmethod
    def _rows(*columns):
        return tuple(
            np.ascontiguousarray(np.atleast_1d(np.asarray(x, dtype=float)))
            for x in np.broadcast_arrays(*columns)
        )

    @staticmethod
    def _swing(swing, scale, h, ground, th, kc, kd):
        """The controls where a time-based policy's leg meets ``ground`` from apex ``h`` (its
        stiffness times ``scale``), the given ``th``, ``kc``, ``kd`` where its tables have none."""
        if swing is None:
            return th, kc, kd
        td = swing.touchdown(h, ground)
        pick = lambda x, given: np.where(np.isfinite(x), x, given)  # noqa: E731
        return pick(td["touchdown_angle"], th), pick(td["k_c"] * scale, kc), pick(td["k_d"] * scale, kd)

    def step(
        self,
        apex_height,
        apex_speed,
        touchdown_angle,
        ground,
        k_c,
        k_d,
        retraction_rate=0.0,
        *,
        swing=None,
        scale=1.0,
        rows=None,
    ) -> PlantSteps:
        """One step of every row (module docstring); the swing leg at ``touchdown_angle`` at the apex,
        retracting at ``retraction_rate`` [rad/s] until it meets the ground, or following the
        time-based tables ``swing`` (their stiffness times ``scale``; ``touchdown_angle``, ``k_c``,
        ``k_d`` where they have no value). ``rows``: the runs' indices (a map plant ignores them)."""
        h, v, th, gr, kc, kd, rate = self._rows(
            apex_height, apex_speed, touchdown_angle, ground, k_c, k_d, retraction_rate
        )
        th, kc, kd = self._swing(swing, scale, h, gr, th, kc, kd)
        n = h.shape[0]
        status, td, t_descent, foot_x = self._descent(h, v, th, gr, rate)
        values = {a: td[:, j] for j, a in enumerate(self._stance.x)}
        values.update(self._stiffness(kc, kd, status))
        S, code = KERNELS.rows(self.call, "stance", values, {}, n, False)
        fresh = (status == 0) & (code != 0)
        status[fresh] = code[fresh]
        lo = S[:, self._lo]
        bottom = S[:, self._bo]
        lo[status != 0] = math.nan
        t_bottom = S[:, self._stance.outputs.index("t_bottom")]
        t_stance = S[:, self._stance.outputs.index("t_stance")]
        first = Compressed(status, td, t_descent, foot_x, t_bottom, bottom, gr, kc)
        return self._finish(first, t_stance, lo, kd)

    def _finish(self, first: Compressed, t_stance, lo, kd) -> PlantSteps:
        """The ascent from liftoff ``lo`` and the steps' record (NaN in the rows that failed)."""
        status = first.status
        apex_h, apex_v, t_ascent, step_length = self._ascent(lo, status, first.foot_x)
        out = PlantSteps(
            status=status,
            touchdown=first.touchdown,
            t_descent=first.t_descent,
            foot_x=first.foot_x,
            t_bottom=first.t_bottom,
            bottom=first.bottom,
            t_stance=t_stance,
            liftoff=lo,
            t_ascent=t_ascent,
            apex_height=apex_h,
            apex_speed=apex_v,
            step_length=step_length,
            k_c=first.k_c,
            k_d=kd,
            ground=first.ground,
        )
        return blank_failed(out)

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

    def compress(
        self,
        apex_height,
        apex_speed,
        touchdown_angle,
        ground,
        k_c,
        retraction_rate=0.0,
        *,
        swing=None,
        scale=1.0,
        rows=None,
    ) -> Compressed:
        """The first stage of a two-stage step: the descent (the leg retracting at ``retraction_rate``,
        or following ``swing`` as in :meth:`step`) and the compression half (k_c) of every row."""
        h, v, th, gr, kc, rate = self._rows(
            apex_height, apex_speed, touchdown_angle, ground, k_c, retraction_rate
        )
        th, kc, _ = self._swing(swing, scale, h, gr, th, kc, kc)
        status, td, t_descent, foot_x = self._descent(h, v, th, gr, rate)
        bottom, t_half = self._run_half("touchdown", td, "k_c", kc, status)
        return Compressed(status, td, t_descent, foot_x, t_half, bottom, gr, kc)

    def _run_half(self, start: str, rows: np.ndarray, key: str, stiffness: np.ndarray, status: np.ndarray):
        """The half map from ``start`` on the polar ``rows`` with its stiffness ``key``: its end
        state (NaN where a row failed) and its duration; a fresh failure's code into ``status``."""
        call, spec = self._half(start)
        n = status.shape[0]
        values = {a: rows[:, j] for j, a in enumerate(spec.x)} | {key: stiffness}
        D, code = KERNELS.rows(call, "half", values, {}, n, False)
        fresh = (status == 0) & (code != 0)
        status[fresh] = code[fresh]
        end = D[:, [spec.outputs.index(f"end_{q}") for q in _POLAR]]
        end[status != 0] = math.nan
        return end, D[:, spec.outputs.index("t_half")]

    def decompress(self, first: Compressed, k_d, *, rows=None) -> PlantSteps:
        """The second stage: from :meth:`compress`'s result ``first`` the decompression half with
        k_d, then the ascent."""
        first = first.copy()
        kd = np.broadcast_to(np.asarray(k_d, dtype=float), first.status.shape).copy()
        bottom = first.bottom
        start = np.where(np.isfinite(bottom), bottom, 0.0)
        start[:, 0] = np.where(first.status == 0, start[:, 0], self.params.l0 * 0.9)
        lo, t_half = self._run_half("bottom", start, "k_d", kd, first.status)
        return self._finish(first, first.t_bottom + t_half, lo, kd)


@dataclass
class Compressed:
    """The first stage of a two-stage step of many rows (:meth:`Plant.compress`): ``status``, the
    ``touchdown`` and ``bottom`` polar states (n, 4), ``t_descent``, ``foot_x``, ``t_bottom`` (the
    compression's duration), the ``ground`` the foot met (relative to the apex's) and the ``k_c`` it
    compressed with; a robot plant adds its own records in ``extras``."""

    status: np.ndarray
    touchdown: np.ndarray
    t_descent: np.ndarray
    foot_x: np.ndarray
    t_bottom: np.ndarray
    bottom: np.ndarray
    ground: np.ndarray
    k_c: np.ndarray
    extras: dict = field(default_factory=dict)

    @property
    def ok(self) -> np.ndarray:
        return self.status == int(Status.OK)

    def copy(self) -> Compressed:
        return Compressed(
            *(np.array(getattr(self, f), copy=True) for f in _COMPRESSED), extras=dict(self.extras)
        )


_COMPRESSED = ("status", "touchdown", "t_descent", "foot_x", "t_bottom", "bottom", "ground", "k_c")


def blank_failed(out: PlantSteps) -> PlantSteps:
    """NaN in every value of a row that failed (never a silent number from a failed step)."""
    bad = out.status != 0
    if bad.any():
        for name in ("t_descent", "foot_x", "t_bottom", "t_stance", "t_ascent", "apex_height", "apex_speed"):
            getattr(out, name)[bad] = math.nan
        out.step_length[bad] = math.nan
        for name in ("touchdown", "bottom", "liftoff"):
            getattr(out, name)[bad] = math.nan
    return out
