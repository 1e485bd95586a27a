"""docs/robot.md, .json, figures and clip: the robot study (:mod:`.robot`) written and rendered.

:func:`write` measures, writes ``robot.json`` (6 significant digits), ``robot.md`` (exactly
:func:`render` of the record as written), ``robot_tracking.png`` (the speed and height profiles),
``robot_ramps.png`` (the falls on unknown ramps) and ``robot.gif`` (the identified controller with
its correction on +-10 cm ramps at 4 m/s, MuJoCo's renderer headless, a drawing without GL).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..api.paths import save_figure
from .study import machine, write_files

__all__ = ["TARGETS", "clip", "render", "verdicts", "write"]

#: The targets the study checks (issue: a robot that is not a SLIP).
TARGETS = {
    "prediction": "identified model: one-hop prediction of the next apex within 5 mm and 0.5 % on "
    "held-out hops, in the mean",
    "prediction_max": "the same on every held-out hop",
    "steady": "steady speed error at most 0.5 % at 3-5 m/s",
    "settle": "a speed change settled (within 1 %) in at most 3 hops",
    "ramps": "unknown ramps of +-10 cm at 3, 4, 5 m/s: no fall in 50 runs of 30 hops, where Raibert "
    "falls in some",
    "largest": "the largest ramp amplitude without a fall at least twice Raibert's",
    "cost": "the controller at most 1 ms per hop (iterative)",
    "real_time": "the robot at least 10x real time on one core",
}
_SLIPMAPS = ("slipmaps, identified + correction", "slipmaps, identified", "slipmaps")


def _pct(x) -> str:
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else f"{100 * x:.2f} %"


def _mm(x) -> str:
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else f"{1e3 * x:.1f} mm"


def _cm(x) -> str:
    return "none" if x is None else f"{100 * x:g} cm"


def _best_slipmaps(rec: dict) -> str:
    return next(c for c in _SLIPMAPS if c in rec["controllers"])


def _steady_max(rec: dict, label: str, key: str = "speed_bias") -> float:
    vals = [abs(r.get(key, math.inf)) for r in rec["steady"][label].values()]
    return max(vals) if vals else math.inf


def verdicts(rec: dict) -> list[tuple[str, bool, str]]:
    """Each target (:data:`TARGETS`): (target, met, what was measured)."""
    best = _best_slipmaps(rec)
    ident = rec["identification"]
    held = ident["errors_fitted"]["held_out"]
    out = []
    if held.get("count"):
        ok = held["height_mean"] <= 0.005 and held["speed_rel_mean"] <= 0.005
        text = (
            f"mean {_mm(held['height_mean'])} / {_pct(held['speed_rel_mean'])}, largest "
            f"{_mm(held['height_max'])} / {_pct(held['speed_rel_max'])} ({held['count']} hops; the "
            f"nominal model: mean {_mm(ident['errors_nominal']['held_out']['height_mean'])} / "
            f"{_pct(ident['errors_nominal']['held_out']['speed_rel_mean'])})"
        )
        out.append((TARGETS["prediction"], ok, text))
        worst = held["height_max"] <= 0.005 and held["speed_rel_max"] <= 0.005
        text = (
            f"largest {_mm(held['height_max'])} / {_pct(held['speed_rel_max'])} (the nominal model: "
            f"{_mm(ident['errors_nominal']['held_out']['height_max'])} / "
            f"{_pct(ident['errors_nominal']['held_out']['speed_rel_max'])})"
        )
        out.append((TARGETS["prediction_max"], worst, text))
    steady = _steady_max(rec, best)
    raibert = _steady_max(rec, "Raibert")
    out.append(
        (
            TARGETS["steady"],
            steady <= 0.005,
            f"{best}: at most {_pct(steady)}; Raibert: at most {_pct(raibert)}",
        )
    )

    def settled(label: str) -> str:
        p = rec["profile"][label]
        return (
            "fell"
            if p["falls"]
            else ", ".join("never" if h is None else str(h) for h in p["settle_speed"]) + " hops"
        )

    p = rec["profile"][best]
    ok = not p["falls"] and all(h is not None and h <= 3 for h in p["settle_speed"])
    out.append((TARGETS["settle"], ok, f"{best}: {settled(best)}; Raibert: {settled('Raibert')}"))
    amp = "0.1"
    speeds = list(rec["ramps"][best])
    if all(amp in rec["ramps"][best][v] for v in speeds):
        falls = [rec["ramps"][best][v][amp] for v in speeds]
        r_falls = [rec["ramps"]["Raibert"][v][amp] for v in speeds]
        ok = sum(falls) == 0 and sum(r_falls) > 0
        text = (
            f"{best}: {', '.join(map(str, falls))} of {rec['ramp_runs']} runs fell at "
            f"{', '.join(speeds)} m/s; Raibert: {', '.join(map(str, r_falls))}"
        )
        out.append((TARGETS["ramps"], ok, text))
    mine = [rec["largest"][best][v] for v in speeds]
    theirs = [rec["largest"]["Raibert"][v] for v in speeds]
    ok = all((a or 0.0) >= 2 * (b or 0.0) and a is not None for a, b in zip(mine, theirs, strict=True))
    text = f"{best}: {', '.join(map(_cm, mine))}; Raibert: {', '.join(map(_cm, theirs))}"
    text += f" (at {', '.join(speeds)} m/s)"
    out.append((TARGETS["largest"], ok, text))
    cost = rec["cost"]["slipmaps"]["solve_us"]
    out.append((TARGETS["cost"], cost <= 1000.0, f"{cost:.0f} us per hop (median)"))
    rt = rec["speed"]["real_time"]
    out.append((TARGETS["real_time"], rt >= 10.0, f"{rt:.0f}x real time"))
    return out


def _table(head: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return out + [""]


def render(rec: dict) -> str:
    """docs/robot.md from the record as written (module docstring)."""
    speeds = list(rec["steady"]["Raibert"])
    ctl = rec["controllers"]
    ident = rec["identification"]
    search = rec["raibert_search"]
    best = search["best"]
    L = [
        "# The robot: slipmaps' controllers on a MuJoCo monoped",
        "",
        "A robot is not a SLIP. This page runs slipmaps' controllers, unchanged, on a planar monoped "
        "simulated in MuJoCo (`slipmaps.runtime.robot`: a 30 kg body, a 1 m leg whose series-elastic "
        "spring the controller sets, k_c until the bottom and k_d after it, a 0.6 kg foot that hits the "
        "ground and is caught by the leg's stop, a hip servo, stiff contacts that let the foot bounce "
        "and skid), side by side with Raibert's controller, the baseline every roboticist knows. "
        "Every number below comes from `robot.json`, measured by one command:",
        "",
        "```bash",
        "python3 -m pip install -e '.[robot]'",
        "slipmaps robot            # this page, its record, figures and clip (--quick: the small version)",
        "slipmaps run --plant mujoco examples/robot_speeds.toml --gif robot_run.gif",
        "```",
        "",
        'A scenario runs on the robot with `plant = "mujoco"` (or a `[plant]` table of `kind = '
        '"mujoco"` and the robot\'s parameters and terrain: [scenarios](scenarios.md)); every policy '
        "(`apex`, `retraction`, `time-based`, two-stage steps, `raibert`) runs on it as on the exact "
        "plant. At each apex the controller measures the robot's apex (the hip's height above the "
        "ground of the last touchdown, the centre of mass's speed), plans on its map and commands "
        "the touchdown angle (the hip servo follows it in flight) and the stiffness; the runs record "
        "the same columns as on the exact plant plus the robot's own (foot skid and bounces, the "
        "energy at each apex and what the touchdown and the liftoff lost, the peaks of the leg force "
        "and the hip torque).",
        "",
        "## A robot is not a SLIP",
        "",
        f"One hop from a {1.1:g} m apex with the ideal SLIP's periodic touchdown angle held from the apex "
        "(k_c = k_d = 20 kN/m), the robot against the exact SLIP with the robot's nominal parameters "
        f"(m = body + thigh = {rec['nominal']['m']:g} kg, l0 = {rec['nominal']['l0']:g} m):",
        "",
    ]
    rows = [
        [
            f"{b['speed']:g}",
            f"{b['angle']:.4f}",
            f"{1e3 * b['height_diff']:+.1f} mm, {100 * b['speed_diff']:+.2f} %",
            _pct(b["energy_lost"]),
            f"{b['loss_touchdown']:.2f} J",
            f"{b['loss_liftoff']:.2f} J",
            _mm(b["skid"]),
            f"{b['bounces']:g}",
        ]
        for b in rec["basics"]
    ]
    L += _table(
        [
            "v [m/s]",
            "angle [rad]",
            "next apex - SLIP's",
            "energy lost",
            "touchdown",
            "liftoff",
            "skid",
            "bounces",
        ],
        rows,
    )
    L += [
        "The touchdown loss is the foot's kinetic energy as it meets the ground; the liftoff loss the "
        "foot's motion relative to the body, caught by the leg's stop and the hip servo.",
        "",
        "## The controllers",
        "",
        "- **Raibert**: foot placement v T_s / 2 + k_v (v - v_d) and thrust by k_d with a height loop "
        "(k_d = k_c (1 + k_0 + k_h (H - h) / l0 + k_i S)) "
        '(`policy = "raibert"`, `slipmaps.RaibertGains`), its gains the best of a search on flat ground '
        "(below);",
        "- **slipmaps**: the apex deadbeat step on `iterative` with the robot's nominal SLIP "
        "(`RobotParams.slip_params()`), the touchdown angle and k_d;",
        "- **slipmaps, identified**: the same on the model `slipmaps.identify` fitted to logged hops "
        "(below: `params`, `model_loss`);",
        f"- **slipmaps, identified + correction**: and the step-to-step correction (`correction = "
        f"{3}`: the mean prediction residual of the last 3 steps taken off the target, steps whose "
        "ground changed by over 1 cm left out).",
        "",
        "### Raibert's gains",
        "",
        f"A grid of {len(search['scores'])} gain sets ("
        + ", ".join(f"{k} in {v}" for k, v in search["grid"].items())
        + ") on flat ground at "
        f"{', '.join(speeds)} m/s, each scored by the mean over the speeds of the root-mean-square relative "
        "error of the next apex (speed and height) after the first hops (a fall: infinite). The best "
        "five (the first is the baseline: " + ", ".join(f"{k} = {best[k]:g}" for k in search["grid"]) + "):",
        "",
    ]
    top = sorted(search["scores"], key=lambda s: math.inf if s["score"] is None else s["score"])[:5]
    names = list(search["grid"])
    L += _table(
        [*names, "score", "falls"],
        [[*(f"{s[k]:g}" for k in names), _pct(s["score"]), str(s["falls"])] for s in top],
    )
    fitted = ", ".join(f"{k} = {v:.5g}" for k, v in ident["fitted"].items())
    L += [
        "## Identification",
        "",
        f"{ident['hops']} hops logged on flat ground under excited targets (the nominal model's "
        "deadbeat; heights uniform in [1.05, 1.15] m, the speed walking by up to 0.3 m/s a step in "
        f'[3, 5] m/s); `slipmaps.identify(runs, map="{ident["map"]}", fit=("k", "l0", "loss"))` on '
        f"three quarters of them: {fitted} (k: the factor on the commanded stiffness, stated as the "
        f"mass {ident['params']['m']:.4g} kg; loss: the fraction of the apex speed lost a step). One-hop "
        f"prediction of the next apex on the {ident['held_out']} held-out hops:",
        "",
    ]
    rows = []
    for label, err in (("nominal SLIP", ident["errors_nominal"]), ("identified", ident["errors_fitted"])):
        e = err["held_out"]
        if e.get("count"):
            rows.append(
                [
                    label,
                    f"{_mm(e['height_mean'])} / {_mm(e['height_max'])}",
                    f"{_pct(e['speed_rel_mean'])} / {_pct(e['speed_rel_max'])}",
                ]
            )
    L += _table(["model", "height error, mean / largest", "speed error, mean / largest"], rows)
    L += [
        "The fitted values absorb the losses; they are not physical (the leg is not stiffer, the foot's "
        "impact is not a speed loss at the apex), they predict.",
        "",
        "## Steady running on flat ground",
        "",
        "The next apex against the target (1.1 m, v) over the hops after the first ones, relative: "
        "mean (the steady error) / root mean square.",
        "",
    ]
    head = ["controller", *[f"{v} m/s speed" for v in speeds], *[f"{v} m/s height" for v in speeds]]
    rows = []
    for c in ctl:
        s = rec["steady"][c]
        cells = [c]
        for key in ("speed", "height"):
            for v in speeds:
                r = s[v]
                cells.append("fell" if r["falls"] else f"{_pct(r[key + '_bias'])} / {_pct(r[key + '_rms'])}")
        rows.append(cells)
    L += _table(head, rows)
    L += [
        "## Speed and height changes",
        "",
        "Hops until the next apex stays within 1 % of a new target (the speed: 3 -> 5 -> 3 m/s; the "
        "height at 4 m/s: 1.1 -> 1.2 -> 1.1 m; on flat ground the planner keeps every apex at least 1.08 m "
        "high, `min_height`):",
        "",
    ]
    rows = []
    for c in ctl:
        p, h = rec["profile"][c], rec["height"][c]
        show = lambda xs: ", ".join("never" if x is None else str(x) for x in xs)  # noqa: E731
        rows.append(
            [
                c,
                "fell" if p["falls"] else show(p["settle_speed"]),
                "fell" if h["falls"] else show(h["settle_height"]),
            ]
        )
    L += _table(["controller", "speed changes", "height changes"], rows)
    up, down = _speed_steps(rec, _best_slipmaps(rec))
    if up is not None:
        L += [
            f"A hop raised the speed by at most {up:.2f} m/s and lowered it by at most {down:.2f} m/s "
            f"({_best_slipmaps(rec)}): the energy a hop can add is what k_d, at most 2 k_c, puts back at "
            "the bottom, so 3 -> 5 m/s takes several hops whatever the controller.",
            "",
        ]
    L += ["![speed and height tracking](robot_tracking.png)", ""]
    amps = list(next(iter(rec["ramps"]["Raibert"].values())))
    L += [
        "## Unknown ramps",
        "",
        f"Heightfield ramps the controllers do not know: levels uniform in +-A, one per segment of about a "
        f"step, joined by 0.5 m ramps; the apex targeted 1.1 m + A above the last touchdown's ground (room "
        "for a rise of A); every controller assumes flat ground; "
        f"{rec['ramp_runs']} runs of {rec['plan']['hops']} hops per speed and amplitude, seeded. Runs that "
        "fell:",
        "",
    ]
    head = ["controller", "speed", *[f"+-{100 * float(a):g} cm" for a in amps], "largest without a fall"]
    rows = []
    for c in ctl:
        for v in speeds:
            rows.append(
                [c, f"{v} m/s", *[str(rec["ramps"][c][v][a]) for a in amps], _cm(rec["largest"][c][v])]
            )
    L += _table(head, rows)
    L += ["![falls on unknown ramps](robot_ramps.png)", ""]
    L += [
        "## Measurement noise",
        "",
        "The apex measured with Gaussian noise of 1 cm and 1 % of the speed (standard deviations), "
        f"{rec['plan']['noise_runs']} runs per speed on flat ground: steady error mean / root mean square, "
        "falls.",
        "",
    ]
    rows = []
    for c in ctl:
        for v in speeds:
            r = rec["noise"][c][v]
            if r["falls"] == r["runs"]:
                rows.append([c, f"{v} m/s", "-", "-", str(r["falls"])])
                continue
            rows.append(
                [
                    c,
                    f"{v} m/s",
                    f"{_pct(r['speed_bias'])} / {_pct(r['speed_rms'])}",
                    f"{_pct(r['height_bias'])} / {_pct(r['height_rms'])}",
                    str(r["falls"]),
                ]
            )
    L += _table(["controller", "speed", "speed error", "height error", "falls"], rows)
    L += [
        "## Cost",
        "",
        f"The robot simulates at {rec['speed']['real_time']:.0f}x real time on one core (a run of "
        f"{rec['plan']['hops']} hops under Raibert's controller, the best of three: MuJoCo at 0.5 ms steps, "
        "the low-level controller at 1 ms, the run loop). The controller's time per hop, the median of a "
        "run planned hop by hop:",
        "",
    ]
    L += _table(["controller", "time per hop"], [[c, f"{rec['cost'][c]['solve_us']:.0f} us"] for c in ctl])
    L += ["## Targets", ""]
    L += _table(
        ["target", "met", "measured"], [[t, "yes" if ok else "**no**", text] for t, ok, text in verdicts(rec)]
    )
    L += [
        "## The robot running",
        "",
        "The identified controller with its correction on unknown +-10 cm ramps at 4 m/s (MuJoCo's "
        "renderer, headless):",
        "",
        "![the robot on ramps](robot.gif)",
        "",
        "## Reproduce",
        "",
        f"`slipmaps robot` ({'the quick version, ' if rec['quick'] else ''}"
        f"{rec['elapsed_s'] / 60:.0f} min on "
        f"{rec.get('machine', 'this machine')}, MuJoCo {rec.get('mujoco', '?')}); `--jobs N` processes, "
        "`--out DIR` elsewhere than docs/.",
        "",
    ]
    return "\n".join(L)


def _speed_steps(rec: dict, label: str) -> tuple[float | None, float | None]:
    """The largest rise and fall of the next apex speed from one hop to the next in the profile."""
    v = np.array([np.nan if x is None else x for x in rec["profile"][label]["series"]["next_apex_speed"]])
    steps = np.diff(v)
    if not np.isfinite(steps).any():
        return None, None
    return float(np.nanmax(steps)), float(-np.nanmin(steps))


def tracking_figure(rec: dict, path) -> Path:
    """The speed and height profiles of every controller against their targets."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    for ax, part, key, unit in ((axes[0], "profile", "speed", "m/s"), (axes[1], "height", "height", "m")):
        first = next(iter(rec[part].values()))["series"]
        target = np.array(first[f"target_{key}"], dtype=float)
        hops = np.arange(1, target.size + 1)
        ax.step(hops, target, where="mid", color="k", lw=1.0, label="target")
        for c in rec["controllers"]:
            y = np.array(
                [np.nan if x is None else x for x in rec[part][c]["series"][f"next_apex_{key}"]], dtype=float
            )
            ax.plot(hops, y, ".-", lw=1.0, ms=3, label=c)
        ax.set_xlabel("hop")
        ax.set_ylabel(f"next apex {key} [{unit}]")
        ax.ticklabel_format(useOffset=False, axis="y")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    return save_figure(fig, path)


def ramps_figure(rec: dict, path) -> Path:
    """Runs that fell on unknown ramps against the amplitude, a panel per speed."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    speeds = list(rec["ramps"]["Raibert"])
    fig, axes = plt.subplots(1, len(speeds), figsize=(3.8 * len(speeds), 3.4), squeeze=False)
    for ax, v in zip(axes[0], speeds, strict=True):
        for c in rec["controllers"]:
            amps = [float(a) for a in rec["ramps"][c][v]]
            falls = [100.0 * f / rec["ramp_runs"] for f in rec["ramps"][c][v].values()]
            ax.plot(100 * np.array(amps), falls, "o-", ms=3, label=c)
        ax.set_title(f"{v} m/s", fontsize=10)
        ax.set_xlabel("ramp amplitude +-A [cm]")
        ax.set_ylabel("runs that fell [%]")
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    return save_figure(fig, path)


def clip(rec: dict, path, hops: int = 6, fps: float = 20.0) -> Path:
    """A GIF of the best slipmaps controller on unknown +-10 cm ramps at 4 m/s (module docstring)."""
    from ..api.params import SlipParams
    from ..control.runs import run_batch
    from ..control.scenarios import Scenario
    from ..robot.render import frames, write_gif
    from .robot import APEX, CORRECTION, ramp_grounds

    ident = rec["identification"]
    params = SlipParams(**ident["params"])
    loss = ident["fitted"].get("loss", 0.0)
    sc = Scenario(
        name="robot clip",
        steps=hops,
        start_height=APEX,
        start_speed=4.0,
        plant="mujoco",
        plant_options={"log_rate": fps},
        known=0,
        params=params,
        model_loss=loss,
        correction=CORRECTION,
    )
    batch = run_batch(sc, ramp_grounds(0.1, 1, hops, seed=40), progress=False)
    images, _ = frames(batch.plant.hoppers[0], width=320, height=240)
    return write_gif(images, path, fps)


def write(
    out: str | Path, *, quick: bool = False, jobs: int | None = None, progress=None, gif: bool = True
) -> list[Path]:
    """Measure and write the study into the directory ``out`` (module docstring): the paths written."""
    from ..robot.mj import mujoco
    from .robot import measure

    rec = measure(quick=quick, jobs=jobs, progress=progress)
    rec["machine"] = machine()
    rec["mujoco"] = mujoco().__version__
    figures = {"robot_tracking.png": tracking_figure, "robot_ramps.png": ramps_figure}
    return write_files(out, "robot", rec, render, figures, clip if gif else None)
