"""The robot study: slipmaps' controllers against Raibert's on the MuJoCo robot (docs/robot.md).

Measured by ``slipmaps robot`` (:func:`measure`; ``--quick`` the small version CI runs), every run
on the robot plant (:mod:`slipmaps.runtime.control.robot_plant`, the default
:class:`~slipmaps.runtime.robot.params.RobotParams`), every step from its own apex:

1. **basics**: one hop from a 1.1 m apex at 3, 4, 5 m/s at the ideal SLIP's periodic angle: the
   robot's next apex against the exact SLIP's, the energy lost and where, the foot's skid;
2. **Raibert's gains**: a grid search on flat ground (:data:`RAIBERT_GRID`) at 3, 4 and 5 m/s,
   :data:`STEADY_HOPS` hops from the target apex; the score of a gain set is the mean over the
   speeds of the root-mean-square relative error of the next apex (speed and height) over the
   hops after the first :data:`SETTLE`, a fall scoring infinity; the best set is Raibert's baseline
   here (and :class:`~slipmaps.runtime.control.raibert.RaibertGains`' defaults);
3. **identification**: hops logged with the nominal model's deadbeat controller under excited
   targets (:func:`excitation`), ``slipmaps.identify`` of ``k``, ``l0`` and ``loss`` with the
   ``iterative`` map, the one-hop prediction error of the nominal and the identified model on
   held-out hops;
4. the **controllers** (:func:`controllers`): Raibert (tuned), slipmaps' apex deadbeat on
   ``iterative`` with the robot's nominal SLIP, with the identified model, and with the identified
   model and the step-to-step correction (the last :data:`CORRECTION` steps' prediction residuals,
   gated at 1 cm of ground change). On each:

   - **steady**: the speed and height error over the hops after :data:`SETTLE` at 3, 4, 5 m/s
     (flat ground, known);
   - **profile**: a speed profile 3 -> 5 -> 3 m/s (:data:`PROFILE`), the hops after each change
     until the speed stays within 1 % of the target;
   - **height**: an apex height profile 1.1 -> 1.2 -> 1.1 m at 4 m/s, the same count;
   - **ramps**: unknown heightfield ramps, levels uniform in +-A (:data:`AMPLITUDES`) per segment
     (one segment about one step long, ramps 0.5 m wide between them), the apex targeted 1.1 + A
     above the last touchdown's ground (room for a rise of A, as the blind-running evaluation of
     docs/control.md gives its runs), :data:`RAMP_RUNS` runs of :data:`STEADY_HOPS` hops per speed:
     the runs that fall; the largest amplitude without a fall;
   - **noise**: apex measurement noise of 1 cm and 1 % of the speed (:data:`NOISE_RUNS` runs):
     the speed and height error, the falls;
   - **cost**: the controller's time per hop [us] (a run planned hop by hop, its median) and the
     robot's simulated seconds per wall second (:func:`real_time`).

Every run's planner (flat ground, known) keeps its apexes at least :data:`FLOOR` high. The runs
are spread over ``jobs`` processes (each compiles the solver it binds once). The record
is deterministic up to the timings (seeded terrain and noise).
"""

from __future__ import annotations

import itertools
import math
import os
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import asdict
from multiprocessing import get_context

import numpy as np

__all__ = [
    "AMPLITUDES",
    "CORRECTION",
    "PROFILE",
    "RAIBERT_GRID",
    "SPEEDS",
    "controllers",
    "excitation",
    "measure",
]

#: The speeds of the steady, ramp and noise runs [m/s]; the apex height of every run [m].
SPEEDS = (3.0, 4.0, 5.0)
APEX = 1.1
#: Hops per run, and the hops left out of the steady errors at a run's start.
STEADY_HOPS = 30
SETTLE = 10
#: The step-to-step correction's window [steps].
CORRECTION = 3
#: The speed profile: (target speed, hops).
PROFILE = ((3.0, 10), (5.0, 15), (3.0, 15))
#: The height profile at 4 m/s: (target height, hops).
HEIGHTS = ((1.1, 10), (1.2, 15), (1.1, 15))
#: The planner's floor [m] (``min_height``): no planned apex below it (the default, l0, leaves the
#: robot, which loses energy at every hop, no room: planned down to l0 on the way to a faster
#: speed, it falls).
FLOOR = 1.08
#: The ramps' amplitudes [m], the runs per amplitude and speed, the noise runs per speed.
AMPLITUDES = (0.025, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4)
RAMP_RUNS = 50
NOISE_RUNS = 10
#: Raibert's gain grid: k_v [s], k_0, k_h, k_i.
RAIBERT_GRID = {
    "k_v": (0.1, 0.15, 0.2, 0.25, 0.3),
    "k_0": (0.2, 0.3, 0.4),
    "k_h": (1.0, 2.0, 4.0),
    "k_i": (0.1, 0.3, 0.6),
}
#: The small version (``--quick``): fewer runs, amplitudes, hops and gains.
QUICK = {
    "speeds": (4.0,),
    "hops": 14,
    "settle": 6,
    "amplitudes": (0.05, 0.1),
    "ramp_runs": 3,
    "noise_runs": 2,
    "grid": {"k_v": (0.15, 0.2), "k_0": (0.2,), "k_h": (2.0,), "k_i": (0.1,)},
    "excitation_runs": 3,
    "excitation_hops": 20,
    "profile": ((3.5, 5), (4.0, 6)),
    "heights": ((1.1, 5), (1.15, 6)),
}
FULL = {
    "speeds": SPEEDS,
    "hops": STEADY_HOPS,
    "settle": SETTLE,
    "amplitudes": AMPLITUDES,
    "ramp_runs": RAMP_RUNS,
    "noise_runs": NOISE_RUNS,
    "grid": RAIBERT_GRID,
    "excitation_runs": 9,
    "excitation_hops": 40,
    "profile": PROFILE,
    "heights": HEIGHTS,
}


# ----------------------------------------------------------------------------------------------
# scenarios
# ----------------------------------------------------------------------------------------------
def _scenario(steps: int, speed: float, *, heights=None, speeds=None, known: int = 1, **changes):
    """A robot run: ``steps`` hops from (APEX, ``speed``), targets the start apex or the profiles."""
    from ..control.scenarios import Scenario

    H = tuple(heights) if heights is not None else (APEX,) * steps
    V = tuple(speeds) if speeds is not None else (speed,) * steps
    return Scenario(
        name="robot",
        steps=steps,
        start_height=APEX,
        start_speed=speed,
        target_height=H,
        target_speed=V,
        plant="mujoco",
        known=known,
        model="iterative",
        min_height=FLOOR,
        **changes,
    )


def controllers(identified: dict | None, raibert: dict | None = None) -> dict[str, dict]:
    """The compared controllers as scenario fields, by label (module docstring); ``identified``:
    the identification's scenario fields (``params``, ``model_loss``), None for the quick record
    without one; ``raibert``: Raibert's gains (default: :class:`RaibertGains`' own)."""
    from ..control.raibert import RaibertGains

    gains = RaibertGains(
        **{k: v for k, v in (raibert or {}).items() if k in RaibertGains.__dataclass_fields__}
    )
    out = {
        "Raibert": {"policy": "raibert", "raibert": gains},
        "slipmaps": {"policy": "apex"},
    }
    if identified is not None:
        out["slipmaps, identified"] = {"policy": "apex", **identified}
        out["slipmaps, identified + correction"] = {"policy": "apex", **identified, "correction": CORRECTION}
    return out


def excitation(runs: int, hops: int, seed: int = 0) -> list[tuple[tuple, tuple]]:
    """Targets that excite the hops identification fits to: per run, heights uniform in
    [1.05, 1.15] m and a speed walking by up to +-0.3 m/s a step within [3, 5] m/s."""
    rng = np.random.default_rng(seed)
    out = []
    for r in range(runs):
        v = [SPEEDS[r % len(SPEEDS)]]
        for _ in range(hops):
            v.append(float(np.clip(v[-1] + rng.uniform(-0.3, 0.3), 3.0, 5.0)))
        out.append((tuple(float(h) for h in rng.uniform(1.05, 1.15, hops)), tuple(v[1:])))
    return out


def ramp_grounds(amplitude: float, runs: int, steps: int, seed: int) -> np.ndarray:
    """Unknown ramps: each run's levels uniform in +-``amplitude`` [m], seeded."""
    return np.random.default_rng([seed, int(round(1e4 * amplitude))]).uniform(
        -amplitude, amplitude, (runs, steps)
    )


# ----------------------------------------------------------------------------------------------
# one task: a batch of runs, summarised (runs in a worker process)
# ----------------------------------------------------------------------------------------------
def _errors(batch, settle: int) -> dict:
    """The next apex's errors against the scenario's targets (the nominal ones, not the planner's
    steps toward them) over the steps after ``settle`` of the runs that did not fall: relative mean
    (signed) and root mean square of speed and height."""
    keep = ~batch.fell
    out = {"runs": int(batch.runs), "falls": int(batch.fell.sum())}
    if not keep.any():
        return out
    for key in ("speed", "height"):
        got = batch[f"next_apex_{key}"][keep, settle:]
        want = batch[f"nominal_{key}"][keep, settle:]
        rel = (got - want) / np.abs(want)
        out[f"{key}_bias"] = float(np.nanmean(rel))
        out[f"{key}_rms"] = float(np.sqrt(np.nanmean(rel**2)))
    return out


def _settle(values: np.ndarray, targets: np.ndarray, tol: float = 0.01) -> list[int | None]:
    """Hops after each change of the target until the value stays within ``tol`` of it (None:
    never, within the segment)."""
    out = []
    changes = [0] + [i for i in range(1, len(targets)) if targets[i] != targets[i - 1]]
    ends = [*changes[1:], len(targets)]
    for a, b in zip(changes[1:], ends[1:], strict=True):
        inside = np.abs(values[a:b] - targets[a:b]) <= tol * np.abs(targets[a:b])  # NaN (a fall): out
        if not inside[-1]:
            out.append(None)
            continue
        last_out = np.flatnonzero(~inside)
        out.append(int(last_out[-1] + 1) + 1 if last_out.size else 1)
    return out


def _task(job: dict) -> dict:
    """One batch of runs (``job``: the scenario, grounds, what to keep); its summary."""
    from ..control.runs import run_batch

    sc = job["scenario"]
    t0 = time.perf_counter()
    batch = run_batch(sc, job.get("grounds"), scalar=job.get("scalar"), progress=False)
    wall = time.perf_counter() - t0
    out = {"key": job["key"]} | _errors(batch, job["settle"])
    simulated = np.nansum(batch["t_descent"] + batch["t_stance"] + batch["t_ascent"])
    out["simulated_s"], out["wall_s"] = float(simulated), wall
    out["solve_us"] = (
        float(np.nanmedian(batch["solve_us"])) if np.isfinite(batch["solve_us"]).any() else math.nan
    )
    if job.get("series"):
        out["series"] = {
            k: [None if not math.isfinite(x) else float(x) for x in batch[k][0]]
            for k in ("next_apex_speed", "next_apex_height")
        }
        for key in ("speed", "height"):
            target = np.asarray(getattr(sc, f"target_{key}"))
            out["series"][f"target_{key}"] = target.tolist()
            out[f"settle_{key}"] = _settle(batch[f"next_apex_{key}"][0], target)
    if job.get("hops"):
        batch.plant = None  # its robots stay in the worker
        out["batch"] = batch  # identification: the logged hops themselves
    if job.get("falls_at"):
        out["fell"] = [bool(x) for x in batch.fell]
    return out


def _run_all(jobs: list[dict], workers: int, bar) -> dict:
    """Every job, in ``workers`` processes (1: here), its summary by key."""
    out = {}
    if workers <= 1:
        for job in jobs:
            res = _task(job)
            out[res["key"]] = res
            bar.update(1)
        return out
    with ProcessPoolExecutor(max_workers=workers, mp_context=get_context("spawn")) as pool:
        for res in pool.map(_task, jobs):
            out[res["key"]] = res
            bar.update(1)
    return out


# ----------------------------------------------------------------------------------------------
# the parts
# ----------------------------------------------------------------------------------------------
def basics(speeds) -> list[dict]:
    """One hop of the robot against the exact SLIP (module docstring, 1)."""
    from ..analysis.gait import fixed_points
    from ..control.plant import Plant
    from ..robot.hopper import Hopper
    from ..robot.params import RobotParams
    from ..robot.swing import hold

    p = RobotParams()
    sp = p.slip_params()
    rows = []
    for v in speeds:
        angle = fixed_points("exact", sp, apex_height=APEX, speed=v)[0].touchdown_angle
        slip = Plant("exact", sp).step(APEX, v, angle, 0.0, sp.k_c, sp.k_d)
        robot = Hopper(p)
        robot.place(APEX, v, leg_angle=angle)
        hop = robot.hop(hold(angle, p.k_c, p.k_d))
        rows.append(
            {
                "speed": v,
                "angle": angle,
                "height_diff": hop.next_apex_height - float(slip.next_apex_height[0]),
                "speed_diff": hop.next_apex_speed / float(slip.next_apex_speed[0]) - 1.0,
                "energy_lost": (hop.energy_start - hop.energy_end) / hop.energy_start,
                "loss_touchdown": hop.loss_touchdown,
                "loss_liftoff": hop.loss_liftoff,
                "skid": hop.skid,
                "bounces": hop.bounces,
            }
        )
    return rows


def _score(res: dict) -> float:
    if res.get("falls", 1) or "speed_rms" not in res:
        return math.inf
    return math.hypot(res["speed_rms"], res["height_rms"])


def raibert_search(plan: dict, workers: int, bar) -> dict:
    """Raibert's gains on flat ground (module docstring, 2)."""
    from ..control.raibert import RaibertGains

    grid = plan["grid"]
    names = list(grid)
    sets = [dict(zip(names, values, strict=True)) for values in itertools.product(*grid.values())]
    jobs = [
        {
            "key": (i, v),
            "scenario": _scenario(plan["hops"], v, policy="raibert", raibert=RaibertGains(**g)),
            "settle": plan["settle"],
        }
        for i, g in enumerate(sets)
        for v in plan["speeds"]
    ]
    res = _run_all(jobs, workers, bar)
    scores = []
    for i, g in enumerate(sets):
        per = [_score(res[i, v]) for v in plan["speeds"]]
        scores.append(
            {**g, "score": float(np.mean(per)), "falls": int(sum(res[i, v]["falls"] for v in plan["speeds"]))}
        )
    best = min(scores, key=lambda s: s["score"])
    return {"grid": {k: list(v) for k, v in grid.items()}, "scores": scores, "best": best}


def identification(plan: dict, workers: int, bar) -> tuple[dict, dict]:
    """Hops under excited targets, identified (module docstring, 3): the record's part and the
    identified model's scenario fields."""
    from ..control.identify import identify

    jobs = []
    for r, (H, V) in enumerate(excitation(plan["excitation_runs"], plan["excitation_hops"])):
        sc = _scenario(len(H), V[0], heights=H, speeds=V)
        jobs.append({"key": r, "scenario": sc, "settle": 0, "hops": True})
    res = _run_all(jobs, workers, bar)
    batches = [res[r]["batch"] for r in sorted(res)]
    got = identify(batches, map="iterative", fit=("k", "l0", "loss"), holdout=0.25, seed=0)
    part = {
        "map": got.map,
        "fit": list(got.fitted),
        "fitted": got.fitted,
        "params": got.params.as_dict(),
        "hops": got.hops,
        "held_out": got.held_out,
        "errors_nominal": got.errors_nominal,
        "errors_fitted": got.errors_fitted,
    }
    return part, {"params": got.params, "model_loss": got.loss}


def _controller_jobs(plan: dict, ctls: dict) -> list[dict]:
    hops, settle = plan["hops"], plan["settle"]
    jobs = []
    for label, fields in ctls.items():
        for v in plan["speeds"]:
            jobs.append(
                {"key": ("steady", label, v), "scenario": _scenario(hops, v, **fields), "settle": settle}
            )
            noisy = _scenario(hops, v, noise_height=0.01, noise_speed=0.01 * v, seed=7, **fields)
            jobs.append(
                {
                    "key": ("noise", label, v),
                    "scenario": noisy,
                    "grounds": np.zeros((plan["noise_runs"], hops)),
                    "settle": settle,
                }
            )
            for a in plan["amplitudes"]:
                clear = [APEX + a] * hops  # the apex above the ground by APEX + A: room for a rise of A
                jobs.append(
                    {
                        "key": ("ramps", label, v, a),
                        "scenario": _scenario(hops, v, known=0, heights=clear, **fields).with_(
                            start_height=APEX + a
                        ),
                        "grounds": ramp_grounds(a, plan["ramp_runs"], hops, seed=int(10 * v)),
                        "settle": settle,
                    }
                )
        for part, prof, base in (("profile", plan["profile"], None), ("height", plan["heights"], 4.0)):
            targets = [t for t, n in prof for _ in range(n)]
            steps = len(targets)
            if base is None:
                sc = _scenario(steps, targets[0], speeds=targets, **fields)
            else:
                sc = _scenario(steps, base, heights=targets, **fields)
            jobs.append({"key": (part, label), "scenario": sc, "settle": 0, "series": True})
        # the controller's time per hop: one run planned hop by hop (scalar solves, timed)
        jobs.append(
            {
                "key": ("cost", label),
                "scenario": _scenario(hops, 4.0, **fields),
                "settle": settle,
                "scalar": True,
            }
        )
    return jobs


def _largest(ramps: dict, amplitudes) -> float | None:
    """The largest amplitude below which no run fell (every amplitude up to it without a fall)."""
    best = None
    for a in sorted(amplitudes):
        if ramps[a]["falls"]:
            break
        best = a
    return best


def measure(quick: bool = False, jobs: int | None = None, progress=None) -> dict:
    """The study's record (module docstring); ``jobs`` processes (default: the machine's cores)."""
    from ..api.progress import Bar
    from ..robot.params import RobotParams

    plan = QUICK if quick else FULL
    workers = jobs or os.cpu_count() or 1
    t0 = time.perf_counter()
    record = {"quick": quick, "plan": _plain(plan), "robot": asdict(RobotParams())}
    record["nominal"] = RobotParams().slip_params().as_dict()
    record["basics"] = basics(plan["speeds"])
    grid = plan["grid"]
    n_grid = math.prod(len(v) for v in grid.values()) * len(plan["speeds"])
    with Bar(n_grid, "Raibert's gains", progress) as bar:
        record["raibert_search"] = raibert_search(plan, workers, bar)
    with Bar(plan["excitation_runs"], "identification", progress) as bar:
        record["identification"], identified = identification(plan, workers, bar)
    ctls = controllers(identified, record["raibert_search"]["best"])
    record["controllers"] = list(ctls)
    jobs_ = _controller_jobs(plan, ctls)
    with Bar(len(jobs_), "controllers", progress) as bar:
        res = _run_all(jobs_, workers, bar)
    out = {"steady": {}, "noise": {}, "ramps": {}, "largest": {}, "profile": {}, "height": {}, "cost": {}}
    for label in ctls:
        out["steady"][label] = {str(v): _strip(res["steady", label, v]) for v in plan["speeds"]}
        out["noise"][label] = {str(v): _strip(res["noise", label, v]) for v in plan["speeds"]}
        ramps = {v: {a: res["ramps", label, v, a] for a in plan["amplitudes"]} for v in plan["speeds"]}
        out["ramps"][label] = {str(v): {str(a): r["falls"] for a, r in ramps[v].items()} for v in ramps}
        out["largest"][label] = {str(v): _largest(ramps[v], plan["amplitudes"]) for v in ramps}
        for part in ("profile", "height"):
            r = res[part, label]
            out[part][label] = {
                "falls": r["falls"],
                "series": r["series"],
                "settle_speed": r["settle_speed"],
                "settle_height": r["settle_height"],
            }
        out["cost"][label] = {"solve_us": res["cost", label]["solve_us"]}
    record.update(out)
    record["ramp_runs"] = plan["ramp_runs"]
    record["speed"] = real_time(plan["hops"])
    record["elapsed_s"] = time.perf_counter() - t0
    return record


def real_time(hops: int, repeat: int = 3) -> dict:
    """The robot's simulated seconds per wall second on one core: a run of ``hops`` hops at 4 m/s
    under Raibert's controller (no solver: the time is the robot's and the run loop's), best of
    ``repeat``, in this process."""
    res = [
        _task({"key": 0, "scenario": _scenario(hops, 4.0, policy="raibert"), "settle": 0})
        for _ in range(repeat)
    ]
    best = min(res, key=lambda r: r["wall_s"])
    return {
        "simulated_s": best["simulated_s"],
        "wall_s": best["wall_s"],
        "real_time": best["simulated_s"] / best["wall_s"],
    }


def _strip(res: dict) -> dict:
    return {k: v for k, v in res.items() if k not in ("key", "series", "batch", "wall_s", "simulated_s")}


def _plain(plan: dict) -> dict:
    return {k: (list(v) if isinstance(v, tuple) else v) for k, v in plan.items()}
