"""The blind-running section of docs/control.md (:func:`.evaluation.blind`'s record, ``blind`` in
control.json): its targets, tables and figure (``control_blind.png``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..api.paths import save_figure
from .evaluation import BLIND_MASS, BLIND_NOISE
from .formats import f as _f
from .formats import largest as _largest
from .formats import share as _share

__all__ = ["BLIND_TARGETS", "blind_figure", "blind_section", "blind_verdicts"]

#: Issue 30's targets, checked against the record.
BLIND_TARGETS = {
    "stiffness": "ground unknown: the time-based policy of the angle and k_d keeps every run at d = 0.5 l0",
    "reach": "every step that policy reaches lands within 1 mm and 0.1 % of its target apex",
    "angle": "ground unknown: the time-based policy of the angle alone keeps every run at d = 0.3 l0 (Wu and "
    "Geyer's figure)",
    "cost": "one policy (64 grounds) within 1 ms with iterative, 0.2 ms with geyer",
}
_STIFF, _ANGLE = "time-based, angle and k_d", "time-based, angle"


def _at(b: dict, label: str, d: float):
    row = b["variants"].get(label)
    if row is None or d not in b["d"]:
        return None
    return row["per_d"][b["d"].index(d)]


def _max(values) -> float | None:
    values = [v for v in values if v is not None]
    return max(values) if values else None


def blind_verdicts(rec: dict) -> list[tuple[str, bool, str]]:
    """Each target of :data:`BLIND_TARGETS`: (target, met, what was measured)."""
    b = rec["blind"]
    out = []
    runs = b["runs"]
    cell = _at(b, _STIFF, 0.5)
    if cell is not None:
        out.append(
            (BLIND_TARGETS["stiffness"], cell["share"] == 1.0, f"{_share(cell['share'])} of {runs} runs")
        )
    row = b["variants"].get(_STIFF)
    if row is not None:
        dh = _max([c["height_error_max"] for c in row["per_d"]])
        dv = _max([c["speed_error_max"] for c in row["per_d"]])
        steps = sum(c["reached"] for c in row["per_d"])
        every = sum(c["steps"] for c in row["per_d"])
        met = dh is not None and dv is not None and dh <= 1e-3 and dv <= 1e-3
        out.append(
            (
                BLIND_TARGETS["reach"],
                met,
                f"largest errors {_f(1000.0 * dh if dh is not None else None)} mm and "
                f"{_f(100.0 * dv if dv is not None else None)} % on the {steps} reached steps "
                f"(of {every} run, every d)",
            )
        )
    cell = _at(b, _ANGLE, 0.3)
    if cell is not None:
        largest = b["variants"][_ANGLE]["largest_d"]
        out.append(
            (
                BLIND_TARGETS["angle"],
                cell["share"] == 1.0,
                f"{_share(cell['share'])} of {runs} runs; no fall up to d = {_largest(largest)}; every "
                "fall a climb that took the energy the angle alone cannot add (below)",
            )
        )
    cost = b.get("policy_cost", {}).get("models", {})
    it, gy = (
        cost.get("iterative: touchdown_angle, 64 grounds"),
        cost.get("geyer: touchdown_angle, 64 grounds"),
    )
    if it is not None and gy is not None:
        two = cost.get("iterative: touchdown_angle and k_d, 64 grounds", {})
        out.append(
            (
                BLIND_TARGETS["cost"],
                it["ms_median"] <= 1.0 and gy["ms_median"] <= 0.2,
                f"median iterative {_f(it['ms_median'])} ms (angle and k_d {_f(two.get('ms_median'))} ms), "
                f"geyer {_f(gy['ms_median'])} ms (load {_f(b['policy_cost']['load'])})",
            )
        )
    return out


def blind_section(rec: dict) -> list[str]:
    """The section's Markdown lines."""
    b = rec["blind"]
    ds, runs = b["d"], b["runs"]
    rs = b["rate_search"]
    lines = [
        "## Running blind: swing-leg policies on unknown ground",
        "",
        f"The ground unknown to the controller (it expects flat ground), `iterative` as the model, the exact "
        f"plant; {runs} seeded runs of {b['steps']} steps at {b['speed']:g} m/s, an apex 1 + d m high, the "
        "ground of each touchdown off the previous one by a uniform draw in +-d l0 (the terrains of the "
        "rough "
        "ground above). The swing-leg policies (`[control] policy`, `slipmaps.swing_policy`): a fixed angle "
        "(the exact map's self-stable gait, no controller); the deadbeat at the apex with the leg retracting "
        f"after it at the best rate of {', '.join(f'{r:g}' for r in rs['rates'])} rad/s (searched on "
        f"{rs['runs']} runs per d: {rs['best']:g} rad/s kept the most); the deadbeat at the apex with the "
        "angle "
        "held (the one-stage controller above); the time-based policy (64 grounds over +-d l0, the controls "
        "as functions of the time since the apex) of the angle alone, whose one target is the apex height, "
        "and of the angle and k_d; the two-stage form (k_d chosen again at the measured bottom). A step "
        "the policy reaches: its plan status is REACHED (for the time-based policies: both knots around the "
        "touchdown reached the target on the model) or, for the apex deadbeat, BLIND (the target reached on "
        "the model on the flat ground it assumed).",
        "",
        "| target | met | measured |",
        "| --- | --- | --- |",
    ]
    for target, met, measured in blind_verdicts(rec):
        lines.append(f"| {target} | {'yes' if met else '**no**'} | {measured} |")
    known = rec.get("rough", {}).get("models", {}).get("iterative", {}).get("known")
    if known is not None:
        lines += [
            "",
            f"Like with like: on *known* ground (the next touchdowns' grounds given to the planner) the apex "
            f"deadbeat keeps every run up to d = {_largest(known['largest_d'])} (rough ground, above); Wu "
            "and "
            "Geyer's figure of about 0.3 l0 is for ground the controller does not know, the table here.",
        ]
    lines += [
        "",
        "**Runs that do not fall**, and the largest d without a fall (searched beyond the grid in steps of "
        "0.05):",
        "",
        "| policy | " + " | ".join(f"d = {d:g}" for d in ds) + " | largest d |",
        "| --- | " + " | ".join("---" for _ in ds) + " | --- |",
    ]
    for row in b["variants"].values():
        cells = " | ".join(_share(c["share"]) for c in row["per_d"])
        lines.append(f"| {row['label']} | {cells} | {_largest(row['largest_d'])} |")
    angle = b["variants"].get(_ANGLE)
    if angle is not None:
        falls = [c for c in angle["per_d"] if c["fall_statuses"]]
        statuses = sorted({k for c in falls for k in c["fall_statuses"]})
        rises = [c["fall_rise_min"] for c in falls if c["fall_rise_min"] is not None]
        lines += [
            "",
            "The angle alone does not change a step's energy (k_c = k_d): height and speed only trade "
            "with each other and with the ground. Holding the apex height above the ground, a climb of "
            f"v0^2 / (2 g) = {_f(b['climb_limit'])} m takes the whole speed of the start; the random walk "
            "of the ground climbs that far above the start in "
            + ", ".join(
                f"{_share(x)} of the terrains at {d:g}" for d, x in zip(ds, b["beyond_climb"], strict=True)
            )
            + ". The policy of the angle alone trades some height for speed where the target is out of "
            "reach (UNREACHABLE knots), "
            + (
                "which keeps more runs than that, but every run it loses is such a climb: "
                if rises and min(rises) > b["climb_limit"]
                else "and "
            )
            + f"its falls ({', '.join(statuses) or 'none'}) come after the ground rose at least "
            f"{_f(min(rises)) if rises else 'n/a'} m above the start. No angle policy adds the energy a "
            "climb takes; k_d does"
            + (
                ", and with it no run falls on the grid."
                if all(
                    c["share"] == 1.0 for c in b["variants"].get(_STIFF, {"per_d": [{"share": 0}]})["per_d"]
                )
                else "."
            ),
        ]
    lines += [
        "",
        "**The next apex against the target** on the steps the policy reaches (largest height error [mm] / "
        "largest speed error [% of the target speed], n/a: not a target), the steps reached of those run, "
        "and "
        "the controller's time per step (the batch over the runs, per run):",
        "",
        "| policy | " + " | ".join(f"d = {d:g}" for d in ds) + " | reached / run | us per step |",
        "| --- | " + " | ".join("---" for _ in ds) + " | --- | --- |",
    ]
    for row in b["variants"].values():
        cells = " | ".join(
            f"{_f(None if c['height_error_max'] is None else 1000.0 * c['height_error_max'])} / "
            f"{_f(None if c['speed_error_max'] is None else 100.0 * c['speed_error_max'])}"
            for c in row["per_d"]
        )
        reached = sum(c["reached"] for c in row["per_d"])
        steps = sum(c["steps"] for c in row["per_d"])
        us = [c.get("solve_us") for c in row["per_d"]]
        us = [u for u in us if u is not None]
        lines.append(
            f"| {row['label']} | {cells} | {reached} / {steps} | {_f(float(np.mean(us))) if us else 'n/a'} |"
        )
    d = b["noise_d"]
    lines += [
        "",
        f"**Noise and mismatch** at d = {d:g}: apex measurements with Gaussian noise of "
        f"{1000 * BLIND_NOISE[0]:g} mm and {BLIND_NOISE[1]:g} m/s (1 % of the speed), or the plant "
        f"{100 * BLIND_MASS:g} % heavier than the model: runs that do not fall, and the mean height error "
        "[mm] "
        "/ mean speed error [%] over every step run:",
        "",
        "| policy | noise: kept | noise: mean errors | mass: kept | mass: mean errors |",
        "| --- | --- | --- | --- | --- |",
    ]
    for row in b["variants"].values():
        n, m = row["noise"], row["mass"]

        def errs(c):
            h, v = c["height_error_mean_all"], c["speed_error_mean_all"]
            return f"{_f(None if h is None else 1000.0 * h)} / {_f(None if v is None else 100.0 * v)}"

        lines.append(
            f"| {row['label']} | {_share(n['share'])} | {errs(n)} | {_share(m['share'])} | {errs(m)} |"
        )
    lines += [
        "",
        "**The retraction rate search** (the apex deadbeat with the leg retracting; runs kept of "
        f"{rs['runs']}):",
        "",
        "| rate [rad/s] | " + " | ".join(f"d = {x:g}" for x in ds) + " |",
        "| --- | " + " | ".join("---" for _ in ds) + " |",
    ]
    for rate, shares in zip(rs["rates"], rs["shares"], strict=True):
        lines.append(f"| {rate:g} | " + " | ".join(_share(s) for s in shares) + " |")
    cost = b.get("policy_cost")
    if cost is not None:
        lines += [
            "",
            "**The cost of one policy** (`slipmaps.swing_policy` over +-0.3 l0 from a 1.3 m, 5 m/s apex, "
            f"the median of 50; the load average was {_f(cost['load'])} on this 2-core machine), and what "
            "its interpolation adds to the next apex (`representation_error()`: largest height [m] and "
            "speed [m/s] errors between the knots): "
            + "; ".join(
                f"`{k}` {_f(v['ms_median'])} ms, {_f(v['height_error'])} / {_f(v['speed_error'])}"
                for k, v in cost["models"].items()
            )
            + ". The solves are one batch on one thread, each a generated Jacobian and 4-6 map evaluations "
            "(`iterative`: 6.3 and 2.2 us per call, measured in a numba loop): 64 of them are over 1 ms. "
            "The interpolation is third order in the knot spacing, so fewer grounds cost less at a known "
            "price: the errors listed.",
        ]
    lines += ["", "![blind running](control_blind.png)", ""]
    return lines


def blind_figure(rec: dict, path) -> Path:
    """The share of runs kept against d, a line per policy."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    b = rec["blind"]
    fig, ax = plt.subplots(figsize=(7.5, 4.5), constrained_layout=True)
    markers = "osD^v<>"
    for k, row in enumerate(b["variants"].values()):
        ax.plot(
            b["d"],
            [100.0 * c["share"] for c in row["per_d"]],
            marker=markers[k % len(markers)],
            label=row["label"],
        )
    ax.set_xlabel("ground change per step, +- d l0 (unknown to the controller)")
    ax.set_ylabel(f"runs that do not fall [% of {b['runs']}]")
    ax.set_ylim(-3, 103)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, frameon=False)
    ax.set_title(f"Running blind at {b['speed']:g} m/s, {b['steps']} steps per run", fontsize=10)
    save_figure(fig, path)
    return Path(path)
