"""The control evaluation: every map as the deadbeat controller's model, the exact simulator as the
plant (the exact map as the model is the ideal). Written into docs/control.md (+ .json, figures) by
``slipmaps run --evaluate`` (:mod:`.report`); its small version (:data:`QUICK`) is re-run by the tests.

Parts (all on the human runner, :data:`~slipmaps.HUMAN_RUNNER`; SI units):

* **tracking**: the six scenarios of examples/ (speed up, slow down, stop, turn around, stairs,
  rough ground) run with each model on the exact plant: per step the next apex's error against the
  target the deadbeat aimed at (the planner's; the nominal one where feasible), mean and max of the
  height error [m] and of the speed error relative to max(|target|, :data:`SPEED_FLOOR`), the plan
  statuses, whether the run fell; with a two-stage variant (``iterative`` at the apex, k_d again at
  the bottom by ``iterative-decompression``);
* **rough ground**: :data:`RUNS` seeded runs of :data:`STEPS` steps at 5 m/s (apex 1 m), the ground
  of each touchdown off the previous one by a uniform draw in +-d l0 for each d of :data:`DS`, the
  same terrains for every model; (a) known to the controller (the next :data:`KNOWN` touchdowns, the
  planner on), (b) unknown (the controller assumes flat ground); the baseline a fixed touchdown angle
  at the exact map's self-stable gait (no controller); the share of runs that do not fall (a plant
  step that fails: no touchdown, a fall, no liftoff...), and the largest d without a fall (searched in
  steps of :data:`D_STEP` beyond the grid);
* **mismatch**: the plant's mass or stiffness off by +5 % and +10 % (:data:`MISMATCHES`): the
  tracking of every scenario, and the rough ground at d = 0.3 known;
* **cost**: the controller's time per step (the deadbeat solve; scalar :meth:`Deadbeat.plan` and
  per row of :meth:`Deadbeat.plan_batch`) on the rough-ground steps of each model, with its
  Jacobian and map evaluations; measured, so machine-dependent (not re-measured by the tests);
* **blind running** (:func:`blind`): ground the controller cannot see (known = 0), the model
  ``iterative``, :data:`RUNS` runs of :data:`STEPS` steps at 5 m/s for each d of :data:`BLIND_DS`,
  the swing-leg policies side by side (:func:`blind_variants`): a fixed angle (no controller); the
  deadbeat at the apex with the leg retracting at the best rate of :data:`RATES` (searched on
  :data:`RATE_RUNS` runs per d: the most runs kept over the grid); the deadbeat at the apex (the
  angle held); the time-based policy (:mod:`.swing`) of the angle alone (its one target the apex
  height) and of the angle and k_d; the two-stage form. Per variant and d: the share of runs that
  do not fall, the largest d without a fall, the next apex's errors against the target on the steps
  the policy reaches (plan status REACHED; BLIND, reached on the flat ground assumed, for the
  apex-set policies), the controller's time per step; at d = :data:`BLIND_D`
  the same with apex-measurement noise (:data:`BLIND_NOISE`) and with the plant's mass off by
  :data:`BLIND_MASS`; the time of one policy of :data:`~.swing.DEFAULT_KNOTS` grounds
  (``slipmaps.swing_policy``, ``geyer`` and ``iterative``).

Constant-stiffness models (``geyer``, the gravity corrections) control the touchdown angle alone (the
energy is not theirs to change: their plant runs at k_c = k_d = k), the others the angle and k_d.
"""

from __future__ import annotations

import math
import os
import time
from pathlib import Path

import numpy as np
from slipmaps.generated.status import Status

from ..analysis.gait import fixed_points
from ..api.index import get, maps
from ..api.params import HUMAN_RUNNER
from ..api.progress import Bar
from .runs import BLIND, NOT_RUN, PLAN_NAMES, run_batch, scenario_of

__all__ = [
    "DS",
    "KNOWN",
    "MISMATCHES",
    "QUICK",
    "RUNS",
    "SCENARIOS",
    "SPEED_FLOOR",
    "STEPS",
    "BLIND_DS",
    "RATES",
    "blind",
    "blind_scenario",
    "blind_variants",
    "evaluate",
    "rough_grounds",
]

#: The scenario files of examples/ the tracking runs, in this order.
SCENARIOS = ("speed_up", "slow_down", "stop", "turn_around", "stairs", "rough_ground")
#: Rough ground: runs per d, steps per run, the ground changes d (fractions of l0), the known horizon.
RUNS, STEPS, DS, KNOWN = 1000, 20, (0.1, 0.2, 0.3, 0.4), 3
#: The search of the largest d without a fall: beyond the grid in steps of D_STEP up to D_MAX, below
#: it by halving down to D_MIN (0 is recorded when even D_MIN falls).
D_STEP, D_MAX, D_MIN = 0.05, 1.0, 0.0125
#: The seed of the rough-ground terrains (run r draws from default_rng([SEED, r])).
SEED = 2024
#: The speed errors are relative to max(|target speed|, SPEED_FLOOR) [m/s] (a hop in place aims at 0).
SPEED_FLOOR = 1.0
#: The plant's mass or stiffness off by these fractions.
MISMATCHES = (("mass", 0.05), ("mass", 0.10), ("stiffness", 0.05), ("stiffness", 0.10))
#: The d of the rough ground with mismatch (known ground).
MISMATCH_D = 0.3
#: How the mismatch row reduces the per-scenario errors.
_REDUCTIONS = (("mean", np.mean), ("max", np.max))
#: Problems timed per model, and repetitions (the best of each).
COST_PROBLEMS, COST_REPEATS = 400, 3

#: Blind running: the ground changes d (fractions of l0), the retraction rates searched [rad/s]
#: (negative: retracting a forward runner's leg) and the runs per rate and d of the search, the d of
#: the noise and mismatch runs, the noise (height [m], speed [m/s]: 1 cm and 1 % of 5 m/s), the
#: plant's mass off by this fraction; the policy timing's repetitions.
BLIND_DS = (0.1, 0.2, 0.3, 0.4, 0.5)
RATES = (-0.5, -1.0, -1.5, -2.0, -2.5, -3.0)
RATE_RUNS = 200
BLIND_D = 0.3
BLIND_NOISE = (0.01, 0.05)
BLIND_MASS = 0.05
POLICY_REPEATS = 50

#: The small version the tests re-run: three models, two scenarios, few runs, no timing.
QUICK = {
    "maps": ("geyer", "iterative", "exact"),
    "scenarios": ("turn_around", "stairs"),
    "runs": 16,
    "ds": (0.2, 0.3),
    "mismatches": (("stiffness", 0.10),),
    "search": False,
    "cost": False,
    "two_stage": True,
    "blind_ds": (0.3, 0.5),
    "rates": (-1.0, -2.0),
    "rate_runs": 8,
}


def _variants(names) -> list[dict]:
    out = [{"label": n, "model": n, "two_stage": False} for n in names]
    if "iterative" in names:
        out.append({"label": "iterative, two-stage", "model": "iterative", "two_stage": True})
    return out


def rough_grounds(d: float, runs: int = RUNS, steps: int = STEPS, l0: float = 1.0) -> np.ndarray:
    """The absolute touchdown grounds (runs, steps): per run the first touchdown on the start's
    ground, then the cumulative sum of uniform changes in +-d l0 (run r seeded by [SEED, r]: the
    same terrain for every model). The first step is flat because the start apex is given: from
    1 m a step up of more than 1 - cos(0.41) = 0.083 l0 has no touchdown at all."""
    out = np.zeros((runs, steps))
    for r in range(runs):
        out[r, 1:] = np.cumsum(np.random.default_rng([SEED, r]).uniform(-d * l0, d * l0, steps - 1))
    return out


def _stats(batch) -> dict:
    """Errors against the planned target over the steps the plant ran, and the statuses."""
    dh, dv = batch.errors()
    v_t = np.abs(batch["target_speed"])
    rel = np.abs(dv) / np.maximum(v_t, SPEED_FLOOR)
    ok = np.isfinite(dh)
    plan = batch["plan_status"][batch["plan_status"] != -2]
    counts = {PLAN_NAMES[int(c)]: int((plan == c).sum()) for c in np.unique(plan)}
    out = {
        "steps": int(ok.sum()),
        "fell": bool(batch.fell.any()),
        "plan": dict(sorted(counts.items())),
        "height_error_mean": float(np.mean(np.abs(dh[ok]))) if ok.any() else math.nan,
        "height_error_max": float(np.max(np.abs(dh[ok]))) if ok.any() else math.nan,
        "speed_error_mean": float(np.mean(rel[ok])) if ok.any() else math.nan,
        "speed_error_max": float(np.max(rel[ok])) if ok.any() else math.nan,
    }
    if batch.fell.any():
        last = batch["plant_status"][0][batch["plant_status"][0] >= 0][-1]
        from slipmaps.generated.status import Status

        out["fall"] = Status(int(last)).name
    return out


def _per_step(batch) -> dict:
    dh, dv = batch.errors()
    rel = np.abs(dv) / np.maximum(np.abs(batch["target_speed"]), SPEED_FLOOR)
    n = len(batch.run(0))
    return {
        "height_error": [float(x) for x in dh[0][:n]],
        "speed_error": [float(x) for x in rel[0][:n]],
        "plan": [PLAN_NAMES[int(c)] for c in batch["plan_status"][0][:n]],
    }


def _scenario(examples: Path, name: str):
    return scenario_of(examples / f"{name}.toml", {})


def tracking(examples: Path, names, scenarios, mismatch=None, bar=None) -> tuple[dict, dict]:
    """Per scenario and model variant: :func:`_stats` of the run; and the per-step errors of the
    iterative and exact models (for the target check)."""
    out, steps = {}, {}
    for s in scenarios:
        sc = _scenario(examples, s)
        if mismatch is not None:
            sc = sc.with_(**{f"mismatch_{mismatch[0]}": mismatch[1]})
        out[s] = {}
        steps[s] = {}
        for var in _variants(names):
            batch = run_batch(sc, model=var["model"], two_stage=var["two_stage"], progress=False)
            out[s][var["label"]] = _stats(batch)
            if var["label"] in ("iterative", "exact") and mismatch is None:
                steps[s][var["label"]] = _per_step(batch)
            if bar is not None:
                bar.update(1)
    return out, steps


def _rough_scenario(model: str | None, known: int, d: float = 0.0, *, angle=None, two_stage: bool = False):
    """The rough-ground scenario: 5 m/s at a 1 m apex (known ground: the planner raises it where the
    coming steps need it); unknown ground: the apex 1 + d above the ground, clear of any step up of
    the distribution; the baseline (``angle``): that apex, a fixed touchdown angle, no controller."""
    h = 1.0 if known else 1.0 + d
    base = {"name": "rough", "steps": STEPS, "start": {"height": h, "speed": 5.0}}
    base["targets"] = {"height": h, "speed": 5.0}
    base["terrain"] = {"known": known}
    sc = scenario_of(base, {})
    if angle is not None:
        return sc.with_(fixed_angle=angle, model="exact")
    return sc.with_(model=model, two_stage=two_stage)


def survival(sc, d: float, runs: int) -> float:
    """The share of ``runs`` rough-ground runs of ``sc`` at ground changes +-d l0 that do not fall."""
    batch = run_batch(sc, rough_grounds(d, runs, sc.steps, sc.params.l0), scalar=False, progress=False)
    return float(1.0 - batch.fell.mean())


def _largest(make, shares: dict[float, float], runs: int, search: bool) -> float | None:
    """The largest d without a fall (``make(d)``: the scenario at d): the grid's, then beyond it in
    steps of D_STEP, or below the grid halving D_STEP (``search``)."""
    clean = [d for d, s in sorted(shares.items()) if s == 1.0]
    if not clean or any(s < 1.0 for d, s in shares.items() if d < max(clean)):
        if not search:
            return (
                max(clean) if clean and all(s == 1.0 for d, s in shares.items() if d < max(clean)) else None
            )
        d = min(shares) / 2.0
        while d >= D_MIN - 1e-12:
            if survival(make(d), d, runs) == 1.0:
                return d
            d /= 2.0
        return 0.0
    best = max(clean)
    if not search:
        return best
    d = round(best + D_STEP, 10)
    while d <= D_MAX + 1e-12:
        if survival(make(d), d, runs) < 1.0:
            break
        best = d
        d = round(d + D_STEP, 10)
    return best


def baseline_angle(height: float = 1.0) -> float:
    """The touchdown angle of the exact map's self-stable gait at ``height``, 5 m/s (the first stable
    one; the first found when none is stable)."""
    gaits = fixed_points("exact", HUMAN_RUNNER, apex_height=height, speed=5.0)
    stable = [g for g in gaits if g.stable]
    return float((stable or list(gaits))[0].touchdown_angle)


def rough(names, ds, runs: int, search: bool, bar=None) -> dict:
    out = {"runs": runs, "steps": STEPS, "speed": 5.0, "d": list(ds), "known_steps": KNOWN, "models": {}}

    def base(d):
        return _rough_scenario(None, 0, d, angle=baseline_angle(1.0 + d))

    shares = {d: survival(base(d), d, runs) for d in ds}
    out["baseline"] = {
        "touchdown_angle": [baseline_angle(1.0 + d) for d in ds],
        "share": [shares[d] for d in ds],
        "largest_d": _largest(base, shares, runs, search),
    }
    if bar is not None:
        bar.update(1)
    for var in _variants(names):
        row = {}
        for mode, known in (("known", KNOWN), ("unknown", 0)):

            def make(d, known=known, var=var):
                return _rough_scenario(var["model"], known, d, two_stage=var["two_stage"])

            shares = {d: survival(make(d), d, runs) for d in ds}
            row[mode] = {"share": [shares[d] for d in ds], "largest_d": _largest(make, shares, runs, search)}
        out["models"][var["label"]] = row
        if bar is not None:
            bar.update(1)
    return out


def mismatch(examples: Path, names, scenarios, variants, runs: int, bar=None) -> dict:
    out = {}
    for quantity, fraction in variants:
        key = f"{quantity} {fraction:+.0%}"
        track, _ = tracking(examples, names, scenarios, mismatch=(quantity, fraction))
        row = {}
        for var in _variants(names):
            cells = [track[s][var["label"]] for s in scenarios]
            steps = [c for c in cells if c["steps"]]
            sc = _rough_scenario(var["model"], KNOWN, MISMATCH_D, two_stage=var["two_stage"])
            sc = sc.with_(**{f"mismatch_{quantity}": fraction})
            keys = [(f"{q}_error_{how}", f) for q in ("height", "speed") for how, f in _REDUCTIONS]
            row[var["label"]] = {k: float(f([c[k] for c in steps])) if steps else math.nan for k, f in keys}
            row[var["label"]] |= {
                "falls": int(sum(c["fell"] for c in cells)),
                "rough_share": survival(sc, MISMATCH_D, runs),
            }
            if bar is not None:
                bar.update(1)
        out[key] = row
    return out


def cost(names, bar=None) -> dict:
    """Per model: the deadbeat's time per step on rough-ground problems (d = 0.2, known), scalar
    (the median and the 90th percentile of the best of COST_REPEATS) and per row of a batch."""
    out = {"problems": COST_PROBLEMS, "load": _load(), "models": {}}
    for name in names:
        sc = _rough_scenario(name, KNOWN)
        batch = run_batch(
            sc, rough_grounds(0.2, COST_PROBLEMS // STEPS + 1, STEPS), scalar=False, progress=False
        )
        ran = batch["plan_status"] >= 0
        h = batch["measured_height"][ran][:COST_PROBLEMS]
        v = batch["measured_speed"][ran][:COST_PROBLEMS]
        H = batch["target_height"][ran][:COST_PROBLEMS]
        V = batch["target_speed"][ran][:COST_PROBLEMS]
        gr = (batch["ground"] - np.concatenate([np.zeros((batch.runs, 1)), batch["ground"][:, :-1]], axis=1))[
            ran
        ]
        gr = gr[:COST_PROBLEMS]
        # the start a run gives each solve: the previous step's angle (the first step's default)
        from .deadbeat import Deadbeat, default_angle

        previous = np.concatenate(
            [np.full((batch.runs, 1), math.nan), batch["touchdown_angle"][:, :-1]], axis=1
        )
        first = default_angle(sc.params, batch["measured_speed"])
        th = np.where(np.isfinite(previous), previous, first)[ran][:COST_PROBLEMS]

        constant = "constant_stiffness" in get(name).requires
        ctl = Deadbeat(
            name, sc.params, controls=("touchdown_angle",) if constant else ("touchdown_angle", "k_d")
        )
        ctl.warm(batch=True)
        times, jac, ev = [], [], []
        for i in range(h.size):
            best = math.inf
            for _ in range(COST_REPEATS):
                t = time.perf_counter()
                r = ctl.plan(
                    float(h[i]),
                    float(v[i]),
                    float(H[i]),
                    float(V[i]),
                    ground=float(gr[i]),
                    touchdown_angle=float(th[i]),
                )
                best = min(best, time.perf_counter() - t)
            times.append(best * 1e6)
            jac.append(r.jacobians)
            ev.append(r.evaluations)
        best = math.inf
        for _ in range(COST_REPEATS):
            t = time.perf_counter()
            ctl.plan_batch(h, v, H, V, ground=gr, touchdown_angle=th)
            best = min(best, time.perf_counter() - t)
        out["models"][name] = {
            "scalar_us_median": float(np.median(times)),
            "scalar_us_p90": float(np.percentile(times, 90)),
            "batch_us_per_row": best * 1e6 / h.size,
            "jacobians_mean": float(np.mean(jac)),
            "evaluations_mean": float(np.mean(ev)),
        }
        if bar is not None:
            bar.update(1)
    return out


def _load() -> float | None:
    try:
        return float(os.getloadavg()[0])
    except (AttributeError, OSError):
        return None


def target_check(steps: dict) -> dict:
    """The iterative model's exact-plant errors on every step where the exact model reached its
    target: within 1 mm and 0.1 % of the target speed (floored at SPEED_FLOOR)?"""
    out = {"steps": 0, "within": 0, "height_error_max": 0.0, "speed_error_max": 0.0, "misses": []}
    for s, per in steps.items():
        if "iterative" not in per or "exact" not in per:
            continue
        ex, it = per["exact"], per["iterative"]
        for n, status in enumerate(ex["plan"]):
            if status != "REACHED":
                continue
            out["steps"] += 1
            if n >= len(it["height_error"]):
                out["misses"].append({"scenario": s, "step": n, "why": "the iterative run ended before"})
                continue
            dh, dv = abs(it["height_error"][n]), abs(it["speed_error"][n])
            out["height_error_max"] = max(out["height_error_max"], dh)
            out["speed_error_max"] = max(out["speed_error_max"], dv)
            if dh <= 1e-3 and dv <= 1e-3:
                out["within"] += 1
            else:
                out["misses"].append({"scenario": s, "step": n, "height_error": dh, "speed_error": dv})
    return out


def blind_variants(rate: float) -> list[dict]:
    """The swing-leg policies of the blind-running evaluation (module docstring), ``rate`` the
    retraction rate of the retraction variant."""
    return [
        {"label": "fixed angle", "fixed": True},
        {"label": "retraction", "policy": "retraction", "retraction_rate": rate},
        {"label": "apex deadbeat", "policy": "apex"},
        {
            "label": "time-based, angle",
            "policy": "time-based",
            "controls": ("touchdown_angle",),
            "aim": "height",
        },
        {
            "label": "time-based, angle and k_d",
            "policy": "time-based",
            "controls": ("touchdown_angle", "k_d"),
        },
        {"label": "two-stage", "policy": "apex", "two_stage": True},
    ]


def blind_scenario(var: dict, d: float):
    """The blind-running scenario of variant ``var`` at ground changes +-d l0 (the ground unknown, the
    apex 1 + d high: :func:`_rough_scenario`); a time-based policy over the grounds +-d l0."""
    if var.get("fixed"):
        return _rough_scenario(None, 0, d, angle=baseline_angle(1.0 + d))
    sc = _rough_scenario("iterative", 0, d, two_stage=var.get("two_stage", False))
    changes = {k: var[k] for k in ("policy", "retraction_rate", "controls", "aim") if k in var}
    if var.get("policy") == "time-based":
        changes["grounds"] = (-d * sc.params.l0, d * sc.params.l0)
    return sc.with_(**changes)


def _blind_stats(batch) -> dict:
    """Share of runs kept, and the errors against the target on the steps the policy reached (of the
    components it aims at: NaN for one that is not a target)."""
    dh, dv = batch.errors()
    aim = batch.scenario.aim
    rel = np.abs(dv) / np.maximum(np.abs(batch["target_speed"]), SPEED_FLOOR)
    # the policy reached the target on its model: on the true ground, or (BLIND) on the flat one
    # the apex-set policies assume
    reached = np.isin(batch["plan_status"], (0, BLIND)) & np.isfinite(dh)
    ran = np.isfinite(dh)
    solve = batch["solve_us"][batch["plan_status"] != NOT_RUN]
    # where the runs fell: the ground's rise above the start at the failed step, and the statuses
    fell = np.flatnonzero(batch.fell)
    last = batch.completed[fell]
    rise = batch.grounds[fell, last] if fell.size else np.zeros(0)
    codes = batch.codes["plant_status"][fell, last]
    statuses = {Status(int(c)).name: int((codes == c).sum()) for c in np.unique(codes)}
    return {
        "fall_rise_min": float(rise.min()) if rise.size else math.nan,
        "fall_rise_median": float(np.median(rise)) if rise.size else math.nan,
        "fall_statuses": dict(sorted(statuses.items())),
        "share": float(1.0 - batch.fell.mean()),
        "steps": int(ran.sum()),
        "reached": int(reached.sum()),
        "height_error_max": float(np.max(np.abs(dh[reached])))
        if reached.any() and aim != "speed"
        else math.nan,
        "speed_error_max": float(np.max(rel[reached])) if reached.any() and aim != "height" else math.nan,
        "height_error_mean_all": float(np.mean(np.abs(dh[ran]))) if ran.any() else math.nan,
        "speed_error_mean_all": float(np.mean(rel[ran])) if ran.any() else math.nan,
        "solve_us": float(np.mean(solve)) if solve.size and np.isfinite(solve).any() else math.nan,
    }


def _blind_run(sc, d: float, runs: int, **changes) -> dict:
    batch = run_batch(
        sc.with_(**changes) if changes else sc,
        rough_grounds(d, runs, sc.steps, sc.params.l0),
        scalar=False,
        progress=False,
    )
    return _blind_stats(batch)


def best_rate(ds, rates, runs: int) -> dict:
    """The retraction rate of :data:`RATES` that keeps the most runs over the grid (ties: the
    smallest magnitude), and every rate's shares."""
    var = blind_variants(0.0)[1]
    shares = {}
    for rate in rates:
        shares[rate] = [
            _blind_run(blind_scenario(var | {"retraction_rate": rate}, d), d, runs)["share"] for d in ds
        ]
    best = max(rates, key=lambda r: (sum(shares[r]), -abs(r)))
    return {"runs": runs, "rates": list(rates), "shares": [shares[r] for r in rates], "best": best}


def policy_cost() -> dict:
    """The time of one swing policy of :data:`~.swing.DEFAULT_KNOTS` grounds (``swing_policy``, the
    human runner's apex 1.3 m, 5 m/s, grounds +-0.3 l0): median and best of POLICY_REPEATS, ms."""
    from .swing import swing_policy

    out = {"load": _load(), "models": {}}
    for name, controls, n in (
        ("geyer", ("touchdown_angle",), 64),
        ("iterative", ("touchdown_angle",), 64),
        ("iterative", ("touchdown_angle", "k_d"), 64),
        ("iterative", ("touchdown_angle", "k_d"), 16),
    ):
        H = 1.3 if len(controls) > 1 else None

        def one(name=name, controls=controls, n=n, H=H):
            return swing_policy(
                name, HUMAN_RUNNER, 1.3, 5.0, H, 5.0, grounds=(-0.3, 0.3), controls=controls, n=n
            )

        error = one().representation_error()
        times = []
        for _ in range(POLICY_REPEATS):
            t = time.perf_counter()
            one()
            times.append(time.perf_counter() - t)
        out["models"][f"{name}: {' and '.join(controls)}, {n} grounds"] = {
            "ms_median": 1e3 * float(np.median(times)),
            "ms_best": 1e3 * float(np.min(times)),
            "height_error": error["height"],
            "speed_error": error["speed"],
        }
    return out


def blind(ds, runs: int, rates, rate_runs: int, search: bool, cost: bool, bar=None) -> dict:
    """The blind-running evaluation (module docstring)."""
    rate = best_rate(ds, rates, rate_runs)
    out = {"runs": runs, "steps": STEPS, "speed": 5.0, "d": list(ds), "rate_search": rate, "variants": {}}
    # an energy-conserving step (the angle alone) that holds the apex height above the ground pays a
    # climb with speed: v^2 = v0^2 - 2 g rise, so a terrain that climbs more than v0^2 / (2 g) above
    # the start is beyond any such policy
    climb = out["speed"] ** 2 / (2.0 * HUMAN_RUNNER.g_f)
    out["climb_limit"] = climb
    out["beyond_climb"] = [float((rough_grounds(d, runs).max(axis=1) > climb).mean()) for d in ds]
    if bar is not None:
        bar.update(1)
    at = min(ds, key=lambda d: abs(d - BLIND_D))
    for var in blind_variants(rate["best"]):
        per_d = {d: _blind_run(blind_scenario(var, d), d, runs) for d in ds}
        shares = {d: per_d[d]["share"] for d in ds}

        def make(d, var=var):
            return blind_scenario(var, d)

        sc = blind_scenario(var, at)
        row = {
            "label": var["label"]
            + (f" {var['retraction_rate']:+g} rad/s" if "retraction_rate" in var else ""),
            "per_d": [per_d[d] for d in ds],
            "largest_d": _largest(make, shares, runs, search),
            "noise": _blind_run(sc, at, runs, noise_height=BLIND_NOISE[0], noise_speed=BLIND_NOISE[1]),
            "mass": _blind_run(sc, at, runs, mismatch_mass=BLIND_MASS),
        }
        if not cost:
            for rec in (*row["per_d"], row["noise"], row["mass"]):
                rec.pop("solve_us")
        out["variants"][var["label"]] = row
        if bar is not None:
            bar.update(1)
    out["noise_d"] = at
    if cost:
        out["policy_cost"] = policy_cost()
    return out


def evaluate(examples: str | Path, *, quick: bool = False, progress=None, parts=None) -> dict:
    """The evaluation record (module docstring): every map (``quick``: :data:`QUICK`); ``parts``
    (default all): the parts to measure, of "tracking" (with the rough ground, the mismatch and the
    cost) and "blind"."""
    parts = ("tracking", "blind") if parts is None else tuple(parts)
    examples = Path(examples)
    cfg = (
        dict(QUICK)
        if quick
        else {
            "maps": tuple(m.name for m in maps()),
            "scenarios": SCENARIOS,
            "runs": RUNS,
            "ds": DS,
            "mismatches": MISMATCHES,
            "search": True,
            "cost": True,
            "two_stage": True,
            "blind_ds": BLIND_DS,
            "rates": RATES,
            "rate_runs": RATE_RUNS,
        }
    )
    names = cfg["maps"]
    n_var = len(_variants(names))
    total = 0
    if "tracking" in parts:
        total += len(cfg["scenarios"]) * n_var + 1 + n_var + len(cfg["mismatches"]) * n_var
        total += len(names) if cfg["cost"] else 0
    if "blind" in parts:
        total += 1 + len(blind_variants(0.0))
    record = {}
    with Bar(total, "control evaluation", progress, unit="parts") as bar:
        if "blind" in parts:
            runs = cfg["runs"]
            args = (cfg["blind_ds"], runs, cfg["rates"], cfg["rate_runs"], cfg["search"], cfg["cost"])
            record["blind"] = blind(*args, bar=bar)
        if "tracking" not in parts:
            return record
        track, steps = tracking(examples, names, cfg["scenarios"], bar=bar)
        record |= {
            "params": HUMAN_RUNNER.as_dict(),
            "settings": {
                "maps": list(names),
                "scenarios": list(cfg["scenarios"]),
                "speed_floor": SPEED_FLOOR,
                "seed": SEED,
                "quick": quick,
            },
            "tracking": track,
            "per_step": steps,
            "target_check": target_check(steps),
            "rough": rough(names, cfg["ds"], cfg["runs"], cfg["search"], bar=bar),
            "mismatch": mismatch(examples, names, cfg["scenarios"], cfg["mismatches"], cfg["runs"], bar=bar),
        }
        if cfg["cost"]:
            record["cost"] = cost(names, bar=bar)
    return record
