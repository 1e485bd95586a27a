"""docs/footholds.md, .json, figures and clip: the footholds study (:mod:`.footholds`) written and
rendered.

:func:`write` measures, writes ``footholds.json`` (6 significant digits), ``footholds.md`` (exactly
:func:`render` of the record as written), ``footholds_course.png`` (the example course hopped at
horizon 1 and at horizon 2: the planned and the flown footholds), ``footholds_success.png`` (the
runs that succeed per family and planner) and ``footholds.gif`` (the example at horizon 2).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..api.paths import save_figure
from .report_format import fails, pct
from .study import machine, write_files

__all__ = ["TARGETS", "clip", "course_figure", "render", "success_figure", "verdicts", "write"]

#: The targets the study checks (the issue: footholds over stepping stones).
TARGETS = {
    "family": "a course family where horizon 1 succeeds in fewer than 80 % of the runs and horizon 2 in "
    "at least 99 %",
    "horizon 3": "horizon 3 no worse than horizon 2 (every family)",
    "placement": "the foot within 1 cm of the planned point (iterative model, exact plant)",
    "replan iterative": "a replan at horizon 2 in at most 2 ms (iterative, one core)",
    "replan geyer": "a replan at horizon 2 in at most 0.5 ms (geyer, one core)",
}
_LIMITS = {"iterative": 2000.0, "geyer": 500.0}


def _mm(x) -> str:
    return "n/a" if x is None or not math.isfinite(x) else f"{1e3 * x:.3g} mm"


def _us(x) -> str:
    return "n/a" if x is None or not math.isfinite(x) else f"{x:.0f} us"


def verdicts(rec: dict) -> list[tuple[str, bool, str]]:
    """Each target (:data:`TARGETS`): (target, met, what was measured)."""
    courses = rec["courses"]
    out = []
    fam = rec["separating"]
    rates = "; ".join(
        f"{f}: {pct(p['horizon 1']['success'])} and {pct(p['horizon 2']['success'])}"
        for f, p in courses.items()
    )
    shown = f"{fam}" if fam else "none"
    out.append((TARGETS["family"], fam is not None, f"{shown} (horizon 1 and 2 succeed in {rates})"))
    worse = [f for f, p in courses.items() if p["horizon 3"]["success"] < p["horizon 2"]["success"]]
    text = "; ".join(f"{f}: {pct(p['horizon 3']['success'])}" for f, p in courses.items())
    out.append(
        (
            TARGETS["horizon 3"],
            not worse,
            f"horizon 3 succeeds in {text}" + (f"; worse: {', '.join(worse)}" if worse else ""),
        )
    )

    def worst(horizons) -> tuple[float, int]:
        got = [s for p in courses.values() for label, s in p.items() if rec["planners"][label] in horizons]
        errors = [s["error_max"] for s in got if s["error_max"] is not None]
        return max(errors, default=math.nan), sum(s["placements"] for s in got)

    (one, n1), (more, n23) = worst((1,)), worst((2, 3))
    out.append(
        (
            TARGETS["placement"],
            max(one, more) <= 0.01,
            f"horizons 2 and 3: at most {_mm(more)} over {n23} footholds; horizon 1: at most {_mm(one)} "
            f"over {n1} (the robot, horizon 2: at most {_mm(rec['robot']['error_max'])})",
        )
    )
    for model in ("iterative", "geyer"):
        t = rec["replan"][model]
        out.append(
            (
                TARGETS[f"replan {model}"],
                t["p95_us"] <= _LIMITS[model],
                f"median {_us(t['median_us'])}, 95th percentile {_us(t['p95_us'])} ({t['replans']} replans, "
                f"{t['candidates_median']:g} stone sequences each at the median)",
            )
        )
    return out


def _table(head: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return out + [""]


def _per_planner(rec: dict, cell, extra: dict | None = None) -> list[list[str]]:
    """A row per family: its name, its ``extra`` cells, then ``cell`` of each planner's summary."""
    return [
        [fam, *(extra or {}).get(fam, [])] + [cell(p[label]) for label in rec["planners"]]
        for fam, p in rec["courses"].items()
    ]


def _range(pair) -> str:
    return f"{pair[0]:g}-{pair[1]:g}"


def render(rec: dict) -> str:
    """docs/footholds.md from the record as written (module docstring)."""
    plan = rec["plan"]
    h0, v0 = rec["apex"]
    L = [
        "# Footholds: stepping stones, planned hops ahead",
        "",
        "A legged robot meets a course of footholds: stepping stones with gaps between them, where "
        "every foot must land inside a stone and the next hop must still be possible. Rutschmann, "
        "Satzinger, Byl and Byl (2012, *Nonlinear model predictive control for rough-terrain robot "
        "hopping*) show on the SLIP that a model-predictive foothold planner needs a horizon of two "
        "hops; this page measures slipmaps' planner, which chooses the stones and the controls of the "
        "next hops on a map's generated Jacobians. Every number comes from `footholds.json`, measured "
        "by one command:",
        "",
        "```bash",
        "slipmaps footholds        # this page, its record, figures and clip (--quick --out DIR: small)",
        "slipmaps run examples/stones.toml",
        "```",
        "",
        "## The planner",
        "",
        'A course (`slipmaps.Course`; in a scenario `[terrain] kind = "stones"`: '
        "[scenarios](scenarios.md)) is stones, each an interval [x_a, x_b] of x at a height, and a "
        "margin: a foot must land at least the margin inside a stone's ends, else it misses and the "
        "run falls there (plant status `MISSED`). Positions are absolute: x from the start apex, "
        "heights from the ground under it ([conventions](conventions.md)). At every apex "
        '(`slipmaps.footholds`, `[control] policy = "footholds"`) the planner:',
        "",
        "1. enumerates the sequences of the next `horizon` stones (of the `lookahead` it sees) whose "
        "feet the hops can reach;",
        "2. solves, for each, a small least squares on the model map's generated apex-return Jacobian, "
        "chained over the hops: every foot as deep inside its stone as the hop allows, the next apexes "
        "near the nominal targets, viable (above a floor, rising after liftoff) and clear of the higher "
        "stones the foot passes over, the least change of the controls (the touchdown angle and k_d);",
        "3. applies the first hop of the feasible sequence of least cost, and plans again at the next "
        "apex (model-predictive), the last plan's controls starting the sequences that continue it.",
        "",
        "The baseline, **deadbeat at the centre** (`horizon = 0`), is the deadbeat step aimed at a "
        "stone: the deadbeat step toward the nominal target picks the stone nearest its foot, and the "
        "deadbeat's own solver puts the foot on that stone's centre and the next apex at the target "
        "height.",
        "",
        "## Courses",
        "",
        f"Each family's courses are drawn as Rutschmann et al. draw theirs (`slipmaps.random_course`: "
        f"{rec['count']} stones, the widths, the gaps and each stone's height change from the last "
        f"uniform in their ranges, the margin {1e3 * rec['margin']:g} mm); {plan['courses']} courses "
        f"of {plan['hops']} hops per family and planner, from a {h0:g} m apex at {v0:g} m/s toward the "
        "same apex (the human runner, `slipmaps.HUMAN_RUNNER`), the `iterative` map the planner's "
        f"model, the `exact` map the plant, every planner seeing the next {rec['lookahead']} stones. "
        "A run succeeds when it hops every hop without a miss or a fall.",
        "",
    ]
    head = ["family", "widths [m]", "gaps [m]", "rises [m]", *rec["planners"]]
    fam = rec["families"]
    shape = {f: [_range(fam[f]["width"]), _range(fam[f]["gap"]), f"+-{fam[f]['rise']:g}"] for f in fam}
    L += _table(
        head, _per_planner(rec, lambda s: f"{pct(s['success'])} ({s['succeeded']}/{s['runs']})", shape)
    )
    L += ["What ended the other runs, and the hops they made on average:", ""]
    L += _table(
        ["family", *rec["planners"]],
        _per_planner(rec, lambda s: f"{fails(s['ended'])}; {s['hops_mean']:.1f} hops"),
    )
    L += [
        "`MISSED`: a foot outside every stone's usable part; `LIFTOFF_DOWNWARD`, `APEX_TOO_LOW`: the "
        "plant's step failed (a hop the plan left with no room to rise, or an apex too low to touch "
        "down).",
        "",
        "## Foot placement",
        "",
        "The plant's foot against the point the plan put it at (its first hop), over every foothold of "
        "the runs; the planned margins (how far inside its stone's usable part the plan put the foot):",
        "",
    ]
    rows = []
    for fam, p in rec["courses"].items():
        for label in rec["planners"]:
            s = p[label]
            rows.append(
                [
                    fam,
                    label,
                    str(s["placements"]),
                    _mm(s["error_mean"]),
                    _mm(s["error_max"]),
                    _mm(s["margin_min"]),
                    _mm(s["margin_median"]),
                ]
            )
    L += _table(
        ["family", "planner", "footholds", "error mean", "error max", "margin min", "margin median"], rows
    )
    L += [
        "On a map plant the foot's flight is the exact one on every map, so the foot lands where the "
        "plan put it to round-off; what differs is the stance and the next apex, which the next plan "
        "starts from.",
        "",
        "## Other models and plants",
        "",
    ]
    g, r = rec["geyer"], rec["robot"]
    rh, rv = rec["robot_apex"]
    L += _table(
        ["", "family", "runs", "success", "ended", "foot error max", "time per hop (median)"],
        [
            [
                "`geyer` model, exact plant, horizon 2",
                g["family"],
                str(g["runs"]),
                pct(g["success"]),
                fails(g["ended"]),
                _mm(g["error_max"]),
                _us(g["us_median"]),
            ],
            [
                f'MuJoCo robot (`plant = "mujoco"`), horizon 2, {rh:g} m at {rv:g} m/s',
                r["family"],
                str(r["runs"]),
                pct(r["success"]),
                fails(r["ended"]),
                _mm(r["error_max"]),
                _us(r["us_median"]),
            ],
        ],
    )
    L += [
        "The robot's model is its nominal SLIP (`RobotParams.slip_params()`); its foot lands off the "
        "plan by its hip servo's lag and the foot's size, and its next apex off the model's by its "
        "losses, which the next plan starts from.",
        "",
        "## The planner's time",
        "",
        "Per hop in the runs above (the plan timed in the run, the median and the 95th percentile; "
        "the runs shared the machine's cores):",
        "",
    ]
    L += _table(
        ["family", *rec["planners"]],
        _per_planner(rec, lambda s: f"{_us(s['us_median'])} / {_us(s['us_p95'])}"),
    )
    L += [
        "A replan at horizon 2 on one core (`replan_times`: a run's apexes planned again, each "
        "warm-started as in the run, the best of 5 per apex; `python benchmarks/bench_footholds.py` "
        "prints the same):",
        "",
    ]
    L += _table(
        ["model", "replans", "median", "95th percentile", "stone sequences (median)"],
        [
            [
                f"`{m}`",
                str(t["replans"]),
                _us(t["median_us"]),
                _us(t["p95_us"]),
                f"{t['candidates_median']:g}",
            ]
            for m, t in rec["replan"].items()
        ],
    )
    L += ["## Targets", ""]
    L += _table(
        ["target", "met", "measured"],
        [[t, "yes" if ok else "**no**", text] for t, ok, text in verdicts(rec)],
    )
    ex = rec["example"]
    L += [
        "## The example",
        "",
        f"Course {ex['seed']} of the family *{ex['family']}*, {ex['hops']} hops at horizon 1 and at "
        "horizon 2: the planned footholds (open triangles) and the flown ones (dots), the miss marked:",
        "",
        "![the example course at horizon 1 and 2](footholds_course.png)",
        "",
        "![runs that succeed per family and planner](footholds_success.png)",
        "",
        "![the example course at horizon 2](footholds.gif)",
        "",
        f"Measured on {rec['machine']} in {rec['elapsed_s'] / 60:.0f} min"
        + (" (the quick version)" if rec["quick"] else "")
        + "; `slipmaps footholds --out DIR` writes elsewhere than docs/.",
        "",
    ]
    return "\n".join(L)


def _example_runs(rec: dict):
    """The example's runs at horizon 1 and 2 (module docstring)."""
    from ..control.runs import run
    from .footholds import course, scenario

    ex = rec["example"]
    stones = course(ex["family"], ex["seed"])
    return stones, {h: run(scenario(stones, h, ex["hops"])) for h in (1, 2)}


def course_figure(rec: dict, path) -> Path:
    """The example course hopped at horizon 1 and 2: the body's path, the stones, the planned and the
    flown footholds."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    stones, runs = _example_runs(rec)
    fig, axes = plt.subplots(2, 1, figsize=(12, 5.6), sharex=True)
    poly = stones.polyline()
    for ax, (h, r) in zip(axes, runs.items(), strict=True):
        path_ = r.path(samples=20)
        ax.fill_between(poly[:, 0], poly[:, 1], poly[:, 1].min(), color="#6d4c41", alpha=0.25, lw=0)
        ax.plot(poly[:, 0], poly[:, 1], color="#6d4c41", lw=1.0)
        ax.plot(path_.x, path_.y, color="#1f4e79", lw=1.0, label="body")
        planned = r.column("planned_foot")
        k = np.clip(r.column("planned_stone").astype(int), 0, None)
        ax.plot(planned, stones.heights[k], "^", mfc="none", color="#e67e22", ms=8, label="planned foot")
        flown = r.column("foot_position")
        ground = r.column("ground")
        missed = r.column("stone") < 0
        ax.plot(flown[~missed], ground[~missed], "o", color="k", ms=3.5, label="flown foot")
        if missed.any():
            ax.plot(flown[missed], ground[missed], "x", color="#c0392b", ms=10, mew=2, label="miss")
        ax.set_title(f"horizon {h}: {r.status}", fontsize=10)
        ax.set_ylabel("y [m]")
        ax.set_ylim(poly[:, 1].min(), max(float(np.nanmax(path_.y)) + 0.2, 1.5))
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8, ncol=4, loc="upper right")
    axes[-1].set_xlabel("x [m]")
    end = max(float(np.nanmax(r.path(samples=4).x)) for r in runs.values()) + 1.0
    axes[-1].set_xlim(-0.5, end)
    fig.tight_layout()
    return save_figure(fig, path)


def success_figure(rec: dict, path) -> Path:
    """The runs that succeed, per family and planner."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    families = list(rec["courses"])
    planners = list(rec["planners"])
    fig, ax = plt.subplots(figsize=(9, 3.8))
    width = 0.8 / len(planners)
    x = np.arange(len(families))
    for j, label in enumerate(planners):
        y = [100.0 * rec["courses"][f][label]["success"] for f in families]
        ax.bar(x + (j - (len(planners) - 1) / 2) * width, y, width, label=label)
    ax.axhline(99.0, color="k", lw=0.8, ls="--")
    ax.axhline(80.0, color="0.5", lw=0.8, ls=":")
    ax.set_xticks(x, families, fontsize=8)
    ax.set_ylabel("runs that succeed [%]")
    ax.set_ylim(0, 105)
    ax.legend(fontsize=8, ncol=len(planners), loc="lower center", bbox_to_anchor=(0.5, 1.0))
    ax.grid(alpha=0.3, axis="y")
    fig.tight_layout()
    return save_figure(fig, path)


def clip(rec: dict, path) -> Path:
    """A GIF of the example course at horizon 2 (module docstring)."""
    from ..control.figures import animate

    _, runs = _example_runs(rec)
    return animate(runs[2], path, fps=15, progress=False)


def write(
    out: str | Path, *, quick: bool = False, jobs: int | None = None, progress=None, gif: bool = True
) -> list[Path]:
    """Measure and write the study into the directory ``out`` (module docstring): the paths written."""
    from .footholds import measure

    rec = measure(quick=quick, jobs=jobs, progress=progress)
    rec["machine"] = machine()
    figures = {"footholds_course.png": course_figure, "footholds_success.png": success_figure}
    return write_files(out, "footholds", rec, render, figures, clip if gif else None)
