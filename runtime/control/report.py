"""docs/control.md, .json and figures: the control evaluation (:mod:`.evaluation`) written and rendered.

:func:`write` measures (the full evaluation, and its small version :data:`~.evaluation.QUICK` for
the tests, in the same record under ``quick``), writes ``control.json`` (6 significant digits),
``control.md`` (exactly :func:`render` of the record), ``control_rough.png`` (the rough-ground
survival), ``control_blind.png`` (blind running: :mod:`.report_blind`) and a figure per scenario of
the ``iterative`` model on the exact plant (``control_<scenario>.png``). ``parts=("blind",)``
re-measures the blind-running part alone into the committed record.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..api.files import rounded
from ..api.index import get
from ..api.paths import save_figure, writing
from .evaluation import MISMATCH_D, SPEED_FLOOR, evaluate
from .formats import f as _f
from .formats import largest as _largest
from .formats import mm as _mm
from .formats import pct as _pct
from .formats import share as _share
from .report_blind import blind_figure, blind_section

__all__ = ["render", "rounded", "summary", "write", "TARGETS"]

#: The issue's targets, checked against the record.
TARGETS = {
    "tracking": "iterative as the model: the exact plant's next apex within 1 mm and 0.1 % of the target "
    f"speed (floored at {SPEED_FLOOR:g} m/s) on every step where the exact map as the model reaches it",
    "rough": "no fall on known ground changes of up to 30 % of l0 at 5 m/s (Wu and Geyer's figure)",
    "cost_iterative": "a step planned in under 50 us with iterative",
    "cost_geyer": "a step planned in under 5 us with geyer",
}


def _cell(c: dict, key: str, fmt) -> str:
    if not c["steps"]:
        return "fell at once"
    text = f"{fmt(c[key + '_error_mean'])} / {fmt(c[key + '_error_max'])}"
    if c["fell"]:
        text += f" (fell: {c.get('fall', '?')})"
    return text


def _tracking(rec: dict) -> list[str]:
    track = rec["tracking"]
    scen = list(track)
    models = list(next(iter(track.values())))
    out = []
    for key, label, fmt in (
        ("height", "next-apex height error [mm], mean / max", _mm),
        ("speed", f"speed error [% of max(|target|, {SPEED_FLOOR:g} m/s)], mean / max", _pct),
    ):
        out += [f"**{label}**", "", "| model | " + " | ".join(f"`{s}`" for s in scen) + " |"]
        out.append("| --- |" + " --- |" * len(scen))
        for m in models:
            out.append(f"| `{m}` | " + " | ".join(_cell(track[s][m], key, fmt) for s in scen) + " |")
        out.append("")
    out += ["**plan statuses** (steps REACHED / UNREACHABLE / MAP_FAILED)", ""]
    out.append("| model | " + " | ".join(f"`{s}`" for s in scen) + " |")
    out.append("| --- |" + " --- |" * len(scen))
    for m in models:
        cells = []
        for s in scen:
            p = track[s][m]["plan"]
            cells.append(f"{p.get('REACHED', 0)} / {p.get('UNREACHABLE', 0)} / {p.get('MAP_FAILED', 0)}")
        out.append(f"| `{m}` | " + " | ".join(cells) + " |")
    out.append("")
    return out


def _rough(rec: dict) -> list[str]:
    r = rec["rough"]
    ds = r["d"]
    head = (
        "| model | "
        + " | ".join(f"known {d:g}" for d in ds)
        + " | "
        + " | ".join(f"unknown {d:g}" for d in ds)
        + " | largest d, known | largest d, unknown |"
    )
    out = [head, "| --- |" + " --- |" * (2 * len(ds) + 2)]
    for m, row in r["models"].items():
        cells = [_share(x) for x in row["known"]["share"]] + [_share(x) for x in row["unknown"]["share"]]
        cells += [_largest(row["known"]["largest_d"]), _largest(row["unknown"]["largest_d"])]
        out.append(f"| `{m}` | " + " | ".join(cells) + " |")
    b = r["baseline"]
    cells = ["-"] * len(ds) + [_share(x) for x in b["share"]] + ["-", _largest(b["largest_d"])]
    out.append("| fixed angle (self-stable gait) | " + " | ".join(cells) + " |")
    return out


def _mismatch(rec: dict) -> list[str]:
    mm = rec["mismatch"]
    keys = list(mm)
    models = list(next(iter(mm.values()))) if mm else []
    out = ["| model | " + " | ".join(keys) + " |", "| --- |" + " --- |" * len(keys)]
    for m in models:
        cells = []
        for k in keys:
            c = mm[k][m]
            cells.append(
                f"{_mm(c['height_error_mean'])} mm / {_pct(c['speed_error_mean'])} %; "
                f"max {_mm(c['height_error_max'])}"
                f" mm / {_pct(c['speed_error_max'])} %; falls {c['falls']}; rough {_share(c['rough_share'])}"
            )
        out.append(f"| `{m}` | " + " | ".join(cells) + " |")
    return out


def _cost(rec: dict) -> list[str]:
    c = rec["cost"]
    out = [
        "| model | scalar, median [us] | scalar, 90th percentile [us] | batch, per row [us] | Jacobians | "
        "evaluations |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for m, row in c["models"].items():
        out.append(
            f"| `{m}` | {_f(row['scalar_us_median'])} | {_f(row['scalar_us_p90'])} | "
            f"{_f(row['batch_us_per_row'])} | "
            f"{_f(row['jacobians_mean'])} | {_f(row['evaluations_mean'])} |"
        )
    return out


def verdicts(rec: dict) -> list[tuple[str, bool, str]]:
    """Each target of :data:`TARGETS`: (target, met, what was measured)."""
    out = []
    tc = rec["target_check"]
    met = tc["steps"] > 0 and tc["within"] == tc["steps"]
    out.append(
        (
            TARGETS["tracking"],
            met,
            f"{tc['within']} of {tc['steps']} steps within; largest errors "
            f"{_mm(tc['height_error_max'])} mm and "
            f"{_pct(tc['speed_error_max'])} %",
        )
    )
    it = rec["rough"]["models"].get("iterative")
    if it is not None:
        ds = rec["rough"]["d"]
        shares = dict(zip(ds, it["known"]["share"], strict=True))
        ok = all(s == 1.0 for d, s in shares.items() if d <= 0.3 + 1e-12)
        out.append(
            (
                TARGETS["rough"],
                ok,
                "iterative, known ground: "
                f"{', '.join(f'{_share(s)} at {d:g}' for d, s in shares.items())} of "
                f"{rec['rough']['runs']} runs do not fall; no fall up to d = {_f(it['known']['largest_d'])}",
            )
        )
    cost = rec.get("cost", {}).get("models", {})
    for key, name, limit in (("cost_iterative", "iterative", 50.0), ("cost_geyer", "geyer", 5.0)):
        if name in cost:
            c = cost[name]
            out.append(
                (
                    TARGETS[key],
                    c["scalar_us_median"] < limit,
                    f"scalar median {_f(c['scalar_us_median'])} us "
                    f"(90th percentile {_f(c['scalar_us_p90'])} us), "
                    f"batch {_f(c['batch_us_per_row'])} us per row",
                )
            )
    return out


def summary(rec: dict) -> str:
    """The paragraph of measured numbers of docs/control_planning.md (tests/test_control_runs.py checks
    the page holds it, so no number there is typed by hand)."""
    tc, r, cost = rec["target_check"], rec["rough"], rec["cost"]["models"]
    ds, models = r["d"], r["models"]
    at = ds.index(MISMATCH_D)
    constant = [n for n in models if n in cost and "constant_stiffness" in get(n).requires]
    kept = [100.0 * models[n]["known"]["share"][at] for n in constant]
    it, two, base = models["iterative"], models["iterative, two-stage"], r["baseline"]
    both = [rec["mismatch"][f"mass +{p}%"]["iterative"] for p in (5, 10)]
    geyer, iterative = cost["geyer"]["scalar_us_median"], cost["iterative"]["scalar_us_median"]
    no_fall = [
        n for n in ("iterative", "exact") if models[n]["known"]["largest_d"] == it["known"]["largest_d"]
    ]
    two_all = 0.0  # the largest d of the grid up to which no two-stage run falls, ground unknown
    for d, share in zip(ds, two["unknown"]["share"], strict=True):
        if share < 1.0:
            break
        two_all = d
    return (
        f"Measured (docs/control.md, .json and figures, written by `slipmaps run --evaluate` in about "
        f"{round(rec['seconds'] / 60.0):.0f} minutes; tests/test_control_runs.py re-runs its small version): "
        f"with `iterative` as the model the exact plant's next apex is within "
        f"{_f(1000.0 * tc['height_error_max'], 2)} mm and {_f(100.0 * tc['speed_error_max'], 2)} % of the "
        f"target speed on every step of the six scenarios ({tc['within']} of {tc['steps']} steps where the "
        f"exact map as the model reaches its target; target 1 mm and 0.1 %). Rough ground at "
        f"{r['speed']:g} m/s, {r['runs']} seeded runs of {r['steps']} steps, the next {r['known_steps']} "
        f"grounds known: no run falls up to ground changes of +-{_f(it['known']['largest_d'])} l0 per step "
        f"with {' or '.join(f'`{n}`' for n in no_fall)} as the model (target: 0.3, Wu and Geyer's figure), "
        f"`geyer-vs` to {_f(models['geyer-vs']['known']['largest_d'])}; the constant-stiffness maps, which "
        f"control the angle alone, keep {min(kept):.0f}-{max(kept):.0f} % of the runs at {MISMATCH_D:g}. "
        f"With the ground unknown (the controller assumes flat ground, its apex 1 + d high) the one-stage "
        f"controller keeps {_share(it['unknown']['share'][0])} at {ds[0]:g} and "
        f"{_share(it['unknown']['share'][at])} at {MISMATCH_D:g}; the two-stage form, k_d chosen again at "
        f"the bottom where the ground is known, keeps every run up to {two_all:g}; the fixed-angle "
        f"self-stable baseline {_share(base['share'][0])} at {ds[0]:g}. A plant 5 % (10 %) heavier than the "
        f"model costs `iterative` {_mm(both[0]['height_error_mean'])} ({_mm(both[1]['height_error_mean'])}) "
        f"mm of mean height error and up to {_pct(both[0]['speed_error_max'])} % "
        f"({_pct(both[1]['speed_error_max'])} %) of the speed, and keeps "
        f"{_share(both[0]['rough_share'])} ({_share(both[1]['rough_share'])}) of the rough-ground runs at "
        f"d = {MISMATCH_D:g}. Cost per step (the scalar `Deadbeat.plan`, warm-started from the previous "
        f"step's angle, median on a shared 2-core machine): `geyer` {_f(geyer)} us (target 5 us: "
        f"{'met' if geyer < 5.0 else 'not met'}), `iterative` {_f(iterative)} us (target 50 us: "
        f"{'met' if iterative < 50.0 else 'not met'}), `exact` {_f(cost['exact']['scalar_us_median'])} us; "
        f"{_f(cost['iterative']['jacobians_mean'])} generated Jacobians and "
        f"{_f(cost['iterative']['evaluations_mean'])} map evaluations per `iterative` solve."
    )


def render(rec: dict) -> str:
    """docs/control.md from the record."""
    s = rec["settings"]
    r = rec["rough"]
    lines = [
        "# Control on the maps: deadbeat steps on the exact plant",
        "",
        "<!-- written by `slipmaps run --evaluate` (runtime/control/report.py) from control.json; "
        "do not edit -->",
        "",
        "Every map as the model of the deadbeat controller (`slipmaps.deadbeat`: the touchdown angle and the "
        "leg stiffness that take the current apex to a target next apex), the exact simulator as the plant "
        "(`slipmaps.run`), the human runner (80 kg, 1 m leg, k_c = 20 kN/m; k_d and k_c bounded to "
        "[0.5, 2] x 20 kN/m, the touchdown angle to +-1.2 rad). Models that accept k_c != k_d control the "
        "touchdown angle and k_d; the constant-stiffness maps (`geyer`, the gravity corrections) the angle "
        "alone, their plant at k_c = k_d = k, so their runs change energy only with the ground. "
        "`iterative, two-stage` plans at the apex with `iterative` and chooses k_d again at the bottom, from "
        "the plant's bottom state, with `iterative-decompression`. Errors are the plant's next apex against "
        "the target the deadbeat aimed at (the planner's, where the nominal one is beyond a step's energy "
        "budget or the coming ground needs another).",
        "",
        "## Targets",
        "",
        "| target | met | measured |",
        "| --- | --- | --- |",
    ]
    for target, met, measured in verdicts(rec):
        lines.append(f"| {target} | {'yes' if met else '**no**'} | {measured} |")
    lines += [
        "",
        "## Tracking on the exact plant",
        "",
        f"The scenarios of examples/ ({', '.join(f'`{x}.toml`' for x in s['scenarios'])}), one run each.",
        "",
        *_tracking(rec),
        "### Where the exact model reaches the target",
        "",
    ]
    tc = rec["target_check"]
    lines.append(
        f"On {tc['steps']} steps the exact map as the model reaches its target; there the `iterative` "
        f"model's run is within 1 mm and 0.1 % on {tc['within']}, its largest errors "
        f"{_mm(tc['height_error_max'])} mm and "
        f"{_pct(tc['speed_error_max'])} %."
        + ("" if not tc["misses"] else f" Misses: {json.dumps(tc['misses'])}.")
    )
    lines += [
        "",
        "## Rough ground",
        "",
        f"Share of {r['runs']} seeded runs of {r['steps']} steps at {r['speed']:g} m/s that do not fall; the "
        "ground of each touchdown differs from the previous one by a uniform draw in +-d l0 (the first "
        "touchdown on the start's ground; the same terrains for every model). Known: the next "
        f"{r['known_steps']} touchdowns' grounds, the planner on, nominal apex 1 m. Unknown: the controller "
        "assumes flat ground and flies an apex 1 + d m high (clear of any step up of the distribution; from "
        "1 m a step up of more than 0.083 l0 leaves no touchdown at all). The baseline: no controller, the "
        "touchdown angle of the exact map's self-stable gait at that apex and 5 m/s, k constant. The largest "
        "d without a fall is searched beyond the grid in steps of 0.05 (below it by halving).",
        "",
        *_rough(rec),
        "",
        "![rough ground](control_rough.png)",
        "",
        "## Model mismatch",
        "",
        "The plant's mass or its springs (the stiffness it runs with, against the commanded one) off by the "
        "fraction: the tracking over every scenario (mean and max of the per-scenario errors, the runs that "
        f"fell), and the share of the rough-ground runs at d = {MISMATCH_D:g}, known ground, that do not "
        "fall.",
        "",
        *_mismatch(rec),
        "",
    ]
    if "cost" in rec:
        c = rec["cost"]
        load = c.get("load")
        lines += [
            "## Cost per step",
            "",
            "The deadbeat solve (`Deadbeat.plan`, warm-started from the previous step's angle, as a run "
            f"does) on {c['problems']} rough-ground steps of each model (d = 0.2, known), the best of 3 per "
            "step; the batch "
            "form (`Deadbeat.plan_batch`, threads) per row; the mean numbers of generated Jacobians and of "
            f"map evaluations per solve. Measured on a shared 2-core machine (load average {_f(load)}): "
            "machine-dependent, not re-measured by the tests.",
            "",
            *_cost(rec),
            "",
        ]
    if "blind" in rec:
        lines += blind_section(rec)
    lines += [
        "## Scenario runs (model `iterative`, plant `exact`)",
        "",
        *[f"![{x}](control_{x}.png)" for x in s["scenarios"]],
        "",
        f"Regenerate: `slipmaps run --evaluate` (about {_f(rec.get('seconds'))} s); the tests re-run the "
        "small version (`quick` in control.json: geyer, iterative and exact on two scenarios, 16 runs of "
        "rough ground).",
        "",
    ]
    return "\n".join(lines)


def rough_figure(rec: dict, path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    r = rec["rough"]
    ds = r["d"]
    models = list(r["models"])
    colors = plt.get_cmap("tab20")(np.linspace(0.0, 1.0, 20))
    markers = "osD^v<>ph*XP"
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.0), sharey=True)
    for ax, mode in zip(axes, ("known", "unknown"), strict=True):
        for k, m in enumerate(models):
            exact = m == "exact"
            ax.plot(
                ds,
                [100 * x for x in r["models"][m][mode]["share"]],
                ls="--" if exact else "-",
                marker="" if exact else markers[k % len(markers)],
                color="k" if exact else colors[(2 * k) % 20 if k < 10 else (2 * k + 1) % 20],
                label=m,
                lw=1.0 if exact else 1.3,
                ms=5,
                zorder=3 if exact else 2,
            )
        if mode == "unknown":
            ax.plot(
                ds, [100 * x for x in r["baseline"]["share"]], ":", color="0.3", lw=2.0, label="fixed angle"
            )
        ax.set_title(f"ground {mode} to the controller", fontsize=10)
        ax.set_xlabel("ground change per step, +- d l0")
        ax.grid(alpha=0.3)
        ax.set_ylim(-3, 103)
    axes[0].set_ylabel(f"runs that do not fall [% of {r['runs']}]")
    handles, labels = axes[1].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=7, fontsize=8, frameon=False)
    fig.suptitle(f"Rough ground at 5 m/s, {r['steps']} steps per run", fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 0.96))
    save_figure(fig, path)
    return Path(path)


def _write_blind(out: Path, examples, progress) -> list[Path]:
    """Re-measure the blind-running part (full and small) into ``out``'s control.json, re-render."""
    import time

    path = out / "control.json"
    if not path.is_file():
        raise ValueError(f"{path} does not exist: run the whole evaluation first (without --blind)")
    record = json.loads(path.read_text())
    t0 = time.perf_counter()
    small = evaluate(examples, quick=True, progress=progress, parts=("blind",))
    full = evaluate(examples, progress=progress, parts=("blind",))
    record["blind"] = full["blind"]
    record["blind_seconds"] = time.perf_counter() - t0
    record.setdefault("quick", {})["blind"] = small["blind"]
    record = rounded(record)
    with writing(path):
        path.write_text(json.dumps(record, indent=1) + "\n")
    written = [path, blind_figure(record, out / "control_blind.png")]
    md = out / "control.md"
    with writing(md):
        md.write_text(render(record))
    return [*written, md]


def write(
    out: str | Path, examples: str | Path, *, quick: bool = False, progress=None, parts=None
) -> list[Path]:
    """Measure and write the evaluation into directory ``out`` (module docstring); ``quick``: the small
    version only (no markdown, no figures: control_quick.json); ``parts=("blind",)``: the blind-running
    part alone, into the committed record. Returns the paths written."""
    import time

    from .figures import run_figure
    from .runs import run, scenario_of

    out = Path(out)
    if parts is not None and tuple(parts) == ("blind",) and not quick:
        return _write_blind(out, examples, progress)
    t0 = time.perf_counter()
    small = evaluate(examples, quick=True, progress=progress)
    if quick:
        path = out / "control_quick.json"
        with writing(path):
            path.write_text(json.dumps(rounded(small), indent=1) + "\n")
        return [path]
    record = evaluate(examples, progress=progress)
    record["quick"] = small
    record["seconds"] = time.perf_counter() - t0
    record = rounded(record)
    written = []
    path = out / "control.json"
    with writing(path):
        path.write_text(json.dumps(record, indent=1) + "\n")
    written.append(path)
    written.append(rough_figure(record, out / "control_rough.png"))
    written.append(blind_figure(record, out / "control_blind.png"))
    for name in record["settings"]["scenarios"]:
        sc = scenario_of(Path(examples) / f"{name}.toml", {})
        written.append(Path(run_figure(run(sc, model="iterative"), out / f"control_{name}.png")))
    path = out / "control.md"
    with writing(path):
        path.write_text(render(record))
    written.append(path)
    return written
