"""The ``footholds`` policy of a run (``[control] policy = "footholds"`` on ``[terrain] kind =
"stones"``): what :func:`~slipmaps.runtime.control.runs.run_batch` asks of it at each step.

:class:`StonesRuns` holds each run's apex x (x_0 = 0, then x + step length: the plant's) and its
last plan. At each apex it plans every run with the :class:`~.footholds.Footholds` planner from the
measured apex over the stones ahead (the scenario's ``lookahead``), toward the nominal targets of the
next ``horizon`` steps, warm-started from the run's last plan; the first hop's controls are applied,
its planned next apex is the step's target and prediction, the ground the model plans on is the
planned stone's. The plant meets the course: a map plant's foot meets the highest stone under it as
it falls (:func:`~.stones.met`, the exact descent of the plant's apex with the commanded angle: the
ground the plant steps on), a robot's foot meets its terrain (the stones as boxes with pits between
them). After the step, a foot outside every stone's usable part is a miss (:meth:`StonesRuns.land`):
the plant status :data:`~.stones.MISSED`, the run ends there.

Plan statuses in a run's records: :data:`FOOTHOLD` (the model's feet inside their stones' usable
parts over the horizon), :data:`NO_FOOTHOLD` (no sequence keeps them inside: the closest one's
controls), MAP_FAILED. The policy's own records (:data:`COLUMNS`): ``apex_x``, ``foot_position``
(the foot's x at the touchdown), ``planned_foot`` (the plan's first foot), ``stone`` (the stone
landed on, -1 a miss), ``planned_stone``, ``planned_margin`` (the plan's first foot's distance inside
its stone's usable part), ``candidates`` (the stone sequences solved).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..api import model
from . import compiled
from .plant import Plant, PlantSteps, blank_failed
from .stones import MISSED, Course, CourseError, met

if TYPE_CHECKING:
    from .footholds import Footholds

__all__ = ["COLUMNS", "FOOTHOLD", "NO_FOOTHOLD", "PLAN_CODES", "StonesRuns", "check_course"]

#: Plan codes of the footholds policy in a run's records (beside the deadbeat's 0-2 and BLIND, 4).
FOOTHOLD, NO_FOOTHOLD = 5, 6
#: A plan's status (:class:`~.footholds.FootholdStatus`, by value) -> its code in the records.
PLAN_CODES = {"FOOTHOLD": FOOTHOLD, "NO_FOOTHOLD": NO_FOOTHOLD, "MAP_FAILED": compiled.MAP_FAILED}
#: The policy's own per-step records (module docstring).
COLUMNS = (
    "apex_x",
    "foot_position",
    "planned_foot",
    "stone",
    "planned_stone",
    "planned_margin",
    "candidates",
)


def check_course(sc, planner: Footholds) -> None:
    """CourseError (one line) for a course the scenario's runner cannot hop: a gap wider than the
    longest hop the planner reaches (its ``reach`` over the nominal step at the start), or a course
    that ends before its steps would (at their shortest reach)."""
    course: Course = sc.stones
    step, _ = planner.nominal_step(sc.target_height[0], sc.target_speed[0])
    longest = (1.0 + planner.reach) * step
    gaps = course.gaps()
    for i, gap in enumerate(gaps):
        if gap + 2.0 * course.margin > longest:
            raise CourseError(
                f"stones: no stone in reach after stone {i}: the gap of {gap:.3g} m to stone {i + 1} (to "
                f"its usable part {gap + 2.0 * course.margin:.3g} m) is wider than the longest hop the "
                f"planner reaches, {longest:.3g} m ({1.0 + planner.reach:g} x the nominal step of "
                f"{step:.3g} m at {sc.target_speed[0]:g} m/s)"
            )
    need = sc.steps * (1.0 - planner.reach) * step
    if course.end < need:
        raise CourseError(
            f"stones: the course ends at {course.end:.3g} m, before {sc.steps} steps of at least "
            f"{(1.0 - planner.reach) * step:.3g} m would ({need:.3g} m): add stones or run fewer steps"
        )


class StonesRuns:
    """The footholds policy of scenario ``sc`` over ``plant`` (module docstring)."""

    columns = COLUMNS

    def __init__(self, sc, plant):
        from .footholds import Footholds  # the planner's solver compiles on import: here, when used

        self.sc = sc
        self.course: Course = sc.stones
        self.planner = Footholds(
            sc.model,
            sc.params,
            horizon=sc.horizon,
            controls=sc.controls,
            bounds=sc.bounds,
            lookahead=sc.lookahead,
            min_height=sc.min_height,
            **sc.model_options,
        )
        check_course(sc, self.planner)
        self.plant = plant
        self.x = np.zeros(0)
        self.plans: list = []

    def start(self, runs: int) -> None:
        """Before a batch's first step: every run at x = 0, no plan yet."""
        self.x = np.zeros(runs)
        self.plans = [None] * runs

    def warm(self) -> None:
        self.planner.warm_up()

    # ------------------------------------------------------------------------------------------
    def plan(self, n: int, idx: np.ndarray, hm, vm, ground_prev) -> dict[str, np.ndarray]:
        """The plans of the runs ``idx`` at step ``n`` from their measured apex (``hm``, ``vm``)
        over the ground ``ground_prev`` (absolute): each run's controls, plan code, the planned
        next apex, the ground the model plans on (relative), the records, the time per run [us]."""
        sc = self.sc
        H = max(sc.horizon, 1)
        cols = [min(n + k, sc.steps - 1) for k in range(H)]
        Ht = np.asarray(sc.target_height)[cols]
        Vt = np.asarray(sc.target_speed)[cols]
        m = idx.size
        keys = ("touchdown_angle", "k_c", "k_d", "next_apex_height", "next_apex_speed", "ground")
        out = {k: np.full(m, math.nan) for k in (*keys, "solve_us", "planned_foot", "planned_margin")}
        out["status"] = np.empty(m, dtype=np.int64)
        out["planned_stone"] = np.full(m, -1.0)
        out["candidates"] = np.zeros(m)
        y = self.course.heights
        for j, r in enumerate(idx):
            plan = self.planner.plan(
                float(hm[j]),
                float(vm[j]),
                self.course,
                x=float(self.x[r]),
                ground=float(ground_prev[j]),
                target_height=Ht,
                target_speed=Vt,
                warm=self.plans[r],
                hops=sc.steps - n,
            )
            self.plans[r] = plan
            out["touchdown_angle"][j] = plan.touchdown_angle
            out["k_c"][j], out["k_d"][j] = plan.k_c[0], plan.k_d[0]
            out["status"][j] = PLAN_CODES[plan.status.value]
            out["solve_us"][j] = plan.solve_us
            out["candidates"][j] = plan.candidates
            k = plan.stones[0]
            if k >= 0:
                out["next_apex_height"][j], out["next_apex_speed"][j] = (
                    plan.apex_heights[0],
                    plan.apex_speeds[0],
                )
                out["ground"][j] = y[k] - ground_prev[j]
                out["planned_foot"][j], out["planned_margin"][j] = plan.feet[0], plan.margins[0]
                out["planned_stone"][j] = k
            else:  # no stone: the nominal target, the ground under the apex
                out["next_apex_height"][j], out["next_apex_speed"][j] = Ht[0], Vt[0]
                out["ground"][j] = 0.0
        return out

    def ground(self, idx: np.ndarray, h, v, th, ground_prev, planned) -> np.ndarray:
        """The ground a map plant steps on (relative to ``ground_prev``): the stone its foot meets
        falling from the true apex (``h``, ``v``) with the angle ``th`` (module docstring), the
        planned one (``planned``) where it meets none (a miss) or for a robot (its own terrain)."""
        if not isinstance(self.plant, Plant) or idx.size == 0:
            return planned
        course = self.course
        K = self.sc.lookahead + 2
        first = np.searchsorted(np.asarray(course.x_b), self.x[idx], side="right")
        cand = first[:, None] + np.arange(K)[None, :]
        cand = np.where(cand < len(course), cand, -1)
        y = course.heights[np.clip(cand, 0, len(course) - 1)]
        p = self.plant.params
        status, out = model.rows(
            "apex_to_touchdown",
            b_y_apex=np.asarray(h)[:, None],
            b_xd_apex=np.asarray(v)[:, None],
            q_th_td=np.asarray(th)[:, None],
            q_r_td=p.q_r_td,
            g_f=p.g_f,
            ground=y - np.asarray(ground_prev)[:, None],
            retraction_rate=0.0,
        )
        foot = np.where(status == 0, out["foot_x"], math.nan).reshape(cand.shape) + self.x[idx][:, None]
        stone = met(course, cand, foot)
        return np.where(stone >= 0, course.heights[np.clip(stone, 0, None)] - ground_prev, planned)

    def land(self, idx: np.ndarray, steps: PlantSteps, values: dict, n: int) -> PlantSteps:
        """The step's landing (module docstring): a foot outside every stone's usable part is
        MISSED; the records; each run's apex x moved on."""
        foot = self.x[idx] + steps.foot_x
        stone = self.course.landing(foot)
        missed = steps.ok & (stone < 0)
        if missed.any():
            steps.status = np.where(missed, MISSED, steps.status)
            steps = blank_failed(steps)
        values["apex_x"][idx, n] = self.x[idx]
        values["foot_position"][idx, n] = foot
        values["stone"][idx, n] = np.where(np.isfinite(foot), stone, math.nan)
        ok = steps.ok
        self.x[idx[ok]] += steps.step_length[ok]
        return steps

    def record(self, idx: np.ndarray, n: int, planned: dict, values: dict) -> None:
        """The plan's records of step ``n``."""
        for key in ("planned_foot", "planned_stone", "planned_margin", "candidates"):
            values[key][idx, n] = planned[key]


__all__ += ["CourseError"]
