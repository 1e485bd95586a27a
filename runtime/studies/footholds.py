"""The footholds study: the planner's horizons against the deadbeat baseline on random stepping-stone
courses (docs/footholds.md).

Measured by ``slipmaps footholds`` (:func:`measure`; ``--quick`` the small version CI runs):

1. **courses**: per family (:data:`FAMILIES`: the stones' widths, the gaps and the height changes,
   drawn as Rutschmann, Satzinger, Byl and Byl (2012) draw theirs: :func:`~slipmaps.random_course`,
   a margin of :data:`MARGIN`), ``courses`` seeded courses of :data:`COUNT` stones, each hopped for
   ``hops`` hops from a 1 m apex at 5 m/s toward the same apex (the human runner; the ``iterative``
   map the planner's model, the ``exact`` map the plant), by each planner (:data:`PLANNERS`: the
   deadbeat step aimed at a stone's centre, horizons 1, 2 and 3; every planner sees the next
   :data:`LOOKAHEAD` stones): the runs that succeed (no miss, no fall), the statuses that ended the
   others, the hops before; the foot placement error (the plant's foot against the planned point)
   over every hop; the planned margins; the planner's time per hop (the plan, timed in the run);
2. **maps**: horizon 2 with ``geyer`` as the model on the first family that separates the
   horizons (:func:`separating`), the same courses;
3. **robot**: horizon 2 on the MuJoCo robot (its nominal SLIP the model, 1.1 m and 4 m/s) on that
   family's courses: success and foot placement (the robot's foot against the plan);
4. **replan**: the planner's time per replan at horizon 2 on one core, ``iterative`` and ``geyer``
   (:func:`replan_times`: a run's apexes planned again, each plan timed, the median and the 95th
   percentile; ``benchmarks/bench_footholds.py`` prints the same).

The runs are spread over ``jobs`` processes (each loads the kernels and compiles the planner it
binds once). The record is deterministic up to the timings (seeded courses, no noise).
"""

from __future__ import annotations

import math
import os
import time
from concurrent.futures import ProcessPoolExecutor
from multiprocessing import get_context

import numpy as np

__all__ = [
    "EXAMPLE_HOPS",
    "FAMILIES",
    "LOOKAHEAD",
    "MARGIN",
    "PLANNERS",
    "course",
    "example",
    "measure",
    "replan_times",
    "scenario",
    "separating",
]

#: The course families: label -> the stones' widths [m], the gaps [m], the height change [m]
#: (uniform in +-rise from one stone to the next).
FAMILIES = {
    "long stones": {"width": (0.8, 1.6), "gap": (0.1, 0.5), "rise": 0.0},
    "stepping stones": {"width": (0.3, 0.6), "gap": (0.2, 0.8), "rise": 0.0},
    "stepping stones, rises": {"width": (0.3, 0.6), "gap": (0.2, 0.8), "rise": 0.1},
    "narrow stones, wide gaps": {"width": (0.2, 0.4), "gap": (0.4, 1.0), "rise": 0.05},
}
#: The planners: label -> the footholds policy's horizon (0: the deadbeat baseline).
PLANNERS = {"deadbeat at the centre": 0, "horizon 1": 1, "horizon 2": 2, "horizon 3": 3}
#: Stones per course, the margin a foot keeps [m], the stones seen ahead.
COUNT = 120
MARGIN = 0.02
LOOKAHEAD = 10
#: The runner's start and target apex [m, m/s]; the robot's.
APEX, SPEED = 1.0, 5.0
ROBOT_APEX, ROBOT_SPEED = 1.1, 4.0
#: Courses per task of a worker.
CHUNK = 10
FULL = {"families": tuple(FAMILIES), "courses": 200, "hops": 30, "robot_courses": 20, "replans": 40}
#: The small version (``--quick``): two families, few short courses.
QUICK = {
    "families": ("long stones", "stepping stones"),
    "courses": 6,
    "hops": 10,
    "robot_courses": 1,
    "replans": 10,
}


def course(family: str, seed: int):
    """Course ``seed`` of a family (:data:`FAMILIES`), seeded by the family's position and ``seed``."""
    from ..control.stones import random_course

    f = FAMILIES[family]
    base = 1000 * list(FAMILIES).index(family)
    return random_course(
        base + seed, count=COUNT, width=f["width"], gap=f["gap"], rise=f["rise"], margin=MARGIN
    )


def scenario(stones, horizon: int, hops: int, *, model: str = "iterative", robot: bool = False):
    """A run of the study on ``stones`` (module docstring)."""
    from ..control.scenarios import Scenario

    h, v = (ROBOT_APEX, ROBOT_SPEED) if robot else (APEX, SPEED)
    return Scenario(
        name="footholds",
        steps=hops,
        start_height=h,
        start_speed=v,
        target_height=(h,) * hops,
        target_speed=(v,) * hops,
        stones=stones,
        lookahead=LOOKAHEAD,
        policy="footholds",
        horizon=horizon,
        model=model,
        plant="mujoco" if robot else "exact",
    )


# ----------------------------------------------------------------------------------------------
# one task: the runs of some courses with one planner, summarised (in a worker process)
# ----------------------------------------------------------------------------------------------
def _task(job: dict) -> dict:
    """The runs of ``job`` (a family, seeds, a horizon, a model, the robot or not): per run its
    outcome, and the hops' foot errors, planned margins and plan times."""
    from ..control.runs import plant_status_name, run

    out = {
        "key": job["key"],
        "succeeded": 0,
        "runs": 0,
        "ended": {},
        "hops": [],
        "error": [],
        "margin": [],
        "us": [],
    }
    for seed in job["seeds"]:
        sc = scenario(
            course(job["family"], seed), job["horizon"], job["hops"], model=job["model"], robot=job["robot"]
        )
        r = run(sc, scalar=True)
        n = len(r)
        out["runs"] += 1
        out["hops"].append(n - int(r.fell))
        if r.fell:
            name = plant_status_name(r.batch.codes["plant_status"][0, n - 1])
            out["ended"][name] = out["ended"].get(name, 0) + 1
        else:
            out["succeeded"] += 1
        ok = r.batch.codes["plant_status"][0, :n] == 0
        error = (r.column("foot_position") - r.column("planned_foot"))[ok]
        out["error"] += np.abs(error[np.isfinite(error)]).tolist()
        out["margin"] += r.column("planned_margin")[ok].tolist()
        out["us"] += r.column("solve_us").tolist()
    return out


def _run_all(jobs: list[dict], workers: int, bar) -> dict:
    """Every job, in ``workers`` processes (1: here), merged by key."""
    out: dict = {}

    def merge(res):
        key = res.pop("key")
        got = out.setdefault(
            key, {"succeeded": 0, "runs": 0, "ended": {}, "hops": [], "error": [], "margin": [], "us": []}
        )
        got["succeeded"] += res["succeeded"]
        got["runs"] += res["runs"]
        for name, count in res["ended"].items():
            got["ended"][name] = got["ended"].get(name, 0) + count
        for k in ("hops", "error", "margin", "us"):
            got[k] += res[k]
        bar.update(1)

    if workers <= 1:
        for job in jobs:
            merge(_task(job))
        return out
    with ProcessPoolExecutor(max_workers=workers, mp_context=get_context("spawn")) as pool:
        for res in pool.map(_task, jobs):
            merge(res)
    return out


def _summary(got: dict, hops: int) -> dict:
    """A planner's runs on a family summarised: success, the statuses that ended the rest, the
    hops before, the foot error, the planned margins, the time per plan."""
    error = np.asarray(got["error"])
    margin = np.asarray(got["margin"])
    margin = margin[np.isfinite(margin)]
    us = np.asarray(got["us"])
    us = us[np.isfinite(us)]
    return {
        "runs": got["runs"],
        "succeeded": got["succeeded"],
        "success": got["succeeded"] / max(got["runs"], 1),
        "ended": dict(sorted(got["ended"].items())),
        "hops_mean": float(np.mean(got["hops"])) if got["hops"] else math.nan,
        "hops_of": hops,
        "error_max": float(error.max()) if error.size else math.nan,
        "error_mean": float(error.mean()) if error.size else math.nan,
        "placements": int(error.size),
        "margin_min": float(margin.min()) if margin.size else math.nan,
        "margin_median": float(np.median(margin)) if margin.size else math.nan,
        "us_median": float(np.median(us)) if us.size else math.nan,
        "us_p95": float(np.percentile(us, 95)) if us.size else math.nan,
    }


def separating(courses: dict) -> str | None:
    """The first family where horizon 1 succeeds in fewer than 80 % of the runs and horizon 2 in
    at least 99 % (the study's target), else None."""
    for family, planners in courses.items():
        if planners["horizon 1"]["success"] < 0.8 and planners["horizon 2"]["success"] >= 0.99:
            return family
    return None


#: Hops of the example run (the figures and the clip).
EXAMPLE_HOPS = 12


def example(family: str, courses: int) -> dict:
    """The example of the figures: the first course of ``family`` (of its first ``courses``) where
    horizon 1 misses within :data:`EXAMPLE_HOPS` hops and horizon 2 does not (else course 0)."""
    from ..control.runs import run

    for seed in range(courses):
        stones = course(family, seed)
        if run(scenario(stones, 1, EXAMPLE_HOPS)).fell and not run(scenario(stones, 2, EXAMPLE_HOPS)).fell:
            return {"family": family, "seed": seed, "hops": EXAMPLE_HOPS}
    return {"family": family, "seed": 0, "hops": EXAMPLE_HOPS}


# ----------------------------------------------------------------------------------------------
# the replan's time
# ----------------------------------------------------------------------------------------------
def replan_times(model: str, horizon: int = 2, replans: int = 60, repeat: int = 5) -> dict:
    """The planner's time per replan on one core (module docstring, 4): a run of ``replans`` hops at
    ``horizon`` on the second family's course 0 with ``model``, then every apex of it planned again
    ``repeat`` times (each with the plan the run had at the apex before as its warm start, as in a
    run), each plan timed: the median and the 95th percentile [us] of the best of the repeats per
    apex, and the candidate sequences per plan (median)."""
    from ..control.footholds import Footholds
    from ..control.runs import run

    stones = course("stepping stones", 0)
    sc = scenario(stones, horizon, replans, model=model)
    r = run(sc, scalar=True)
    planner = Footholds(model, sc.params, horizon=horizon, lookahead=LOOKAHEAD).warm_up()
    n = len(r) - int(r.fell)
    h, v = r.column("measured_height"), r.column("measured_speed")
    x, ground = r.column("apex_x"), np.concatenate([[0.0], r.column("ground")])
    best = np.full(n, math.inf)
    candidates = []
    for _ in range(repeat):
        warm = None
        for i in range(n):
            t0 = time.perf_counter()
            plan = planner.plan(
                h[i],
                v[i],
                stones,
                x=x[i],
                ground=ground[i],
                target_height=APEX,
                target_speed=SPEED,
                warm=warm,
            )
            best[i] = min(best[i], (time.perf_counter() - t0) * 1e6)
            warm = plan
            candidates.append(plan.candidates)
    return {
        "model": model,
        "horizon": horizon,
        "replans": int(n),
        "median_us": float(np.median(best)),
        "p95_us": float(np.percentile(best, 95)),
        "candidates_median": float(np.median(candidates)),
    }


# ----------------------------------------------------------------------------------------------
def _jobs(
    families, planners: dict, courses: int, hops: int, *, model="iterative", robot=False, part="courses"
):
    jobs = []
    for family in families:
        for label, horizon in planners.items():
            for lo in range(0, courses, CHUNK):
                seeds = list(range(lo, min(lo + CHUNK, courses)))
                key = (part, family, label)
                jobs.append(
                    {
                        "key": key,
                        "family": family,
                        "seeds": seeds,
                        "horizon": horizon,
                        "hops": hops,
                        "model": model,
                        "robot": robot,
                    }
                )
    return jobs


def measure(quick: bool = False, jobs: int | None = None, progress=None) -> dict:
    """The study's record (module docstring); ``jobs`` processes (default: the machine's cores; one
    for the quick version)."""
    from ..api.progress import Bar

    plan = QUICK if quick else FULL
    # the quick version's runs take less than a worker's start (its kernels, the planner's binding)
    workers = jobs or (1 if quick else os.cpu_count() or 1)
    t0 = time.perf_counter()
    record = {
        "quick": quick,
        "plan": {k: list(v) if isinstance(v, tuple) else v for k, v in plan.items()},
        "families": {
            f: {k: list(v) if isinstance(v, tuple) else v for k, v in FAMILIES[f].items()}
            for f in plan["families"]
        },
        "planners": dict(PLANNERS),
        "count": COUNT,
        "margin": MARGIN,
        "lookahead": LOOKAHEAD,
        "apex": [APEX, SPEED],
        "robot_apex": [ROBOT_APEX, ROBOT_SPEED],
    }
    hops = plan["hops"]
    work = _jobs(plan["families"], PLANNERS, plan["courses"], hops)
    with Bar(len(work), "footholds: courses", progress) as bar:
        got = _run_all(work, workers, bar)
    record["courses"] = {
        f: {label: _summary(got["courses", f, label], hops) for label in PLANNERS} for f in plan["families"]
    }
    family = separating(record["courses"]) or plan["families"][-1]
    record["separating"] = separating(record["courses"])
    extra = _jobs([family], {"horizon 2": 2}, plan["courses"], hops, model="geyer", part="geyer")
    extra += _jobs([family], {"horizon 2": 2}, plan["robot_courses"], hops, robot=True, part="robot")
    with Bar(len(extra), "footholds: geyer, robot", progress) as bar:
        got = _run_all(extra, workers, bar)
    record["geyer"] = {"family": family, **_summary(got["geyer", family, "horizon 2"], hops)}
    record["robot"] = {"family": family, **_summary(got["robot", family, "horizon 2"], hops)}
    record["example"] = example(family, plan["courses"])
    record["replan"] = {m: replan_times(m, replans=plan["replans"]) for m in ("iterative", "geyer")}
    record["elapsed_s"] = time.perf_counter() - t0
    return record
