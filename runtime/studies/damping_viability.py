"""Heim et al.'s damping study on slipmaps' viability API (docs/damping.md, "Viability with damping").

Heim, Millard, Le Mouel and Badri-Spröwitz ("A little damping goes a long way: a simulation study
of how damping influences task-level stability in running", Biology Letters 2020; their code is
sheim/vibly, demos/damping_study/) compute, for a guinea fowl's leg with a damper, the viable set
of (apex height, apex speed) x angle of attack for 21 damping values. Their setting
(demos/damping_study/compute_measure_damping.py, bird 0 of guineafowl_fit.pickle):

* :data:`BIRD`: the mass, the leg length L (spring rest length 0.9 L plus the actuator's 0.1 L), the
  stiffness their SLIP fit gives (``create_open_loop_trajectories`` from 650 N/m: the SLIP of leg
  L whose apex at the bird's height and speed is periodic at the bird's angle), gravity, the apex;
* :data:`HEIM_DAMPING`: their damping values, the damper coefficient over the stiffness d/k [s];
* :data:`FULL`: their grids, apex height 0.05 ... 0.5 m (91), speed 0 ... 10 m/s (101), angle of
  attack 0 ... 90 deg (91; slipmaps takes angles below 90 deg, and at 90 deg their foot touches
  down at hip height, so that step always fails: 0 ... 89 deg here, 90 angles).

Their damper sits in series with the leg spring (spring - [damper | actuator] - foot) and their
actuator is a force: the open-loop leg-force history of the undamped SLIP gait, started at the
touchdown. slipmaps' damper is in parallel with the spring (``c``) and its actuation is the
stiffness after the bottom k_d. The damper coefficient is kept (c = d, so c/k = d/k) and stated as
a damping ratio c / (2 sqrt(k m)). Per ratio, :func:`nominal_gait` finds k_d (and the touchdown
angle) that make the bird's apex periodic with that damping (``slipmaps.deadbeat``, controls
touchdown angle and k_d, the exact map), or, where no control reaches it, the lowest apex at the
bird's speed that is periodic; :func:`measure` then computes the viable set on the grid with that
k_d fixed and the touchdown angle as the action (``slipmaps.viability``, the exact map, vibly's rule
for a next state beyond the grid: ``outside="edge"``).

The measure (:func:`measure`): their "viable portion of Q", the viable pairs over all pairs of the
grid, which is the mean over the grid's states of the share of viable angles (vibly's S_M); beside
it the kernel's states and the measure at the gait's apex (vibly's ``interp_measure``: the mean of
S_M over the nodes of the apex's cell); their figure's measure, S_M after one step from the gait
onto each of their ground heights (:func:`post_step`); and, as the control for the undamped row,
the undamped leg on the bird's own energy level (:func:`energy_level`: an energy-conserving step on
a (height, speed) grid loses its kernel to the conservative rule). ``slipmaps damping-viability``
writes damping_viability.json and .png (:func:`write`).
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from ..analysis.viability import viability
from ..api.index import EXACT
from ..api.params import SlipParams
from ..api.progress import Bar

__all__ = [
    "BIRD",
    "HEIM_DAMPING",
    "GROUNDS",
    "FULL",
    "QUICK",
    "K_D_BOUNDS",
    "Grid",
    "Gait",
    "params",
    "ratio_of",
    "ratios",
    "nominal_gait",
    "cell_measure",
    "post_step",
    "energy_level",
    "measure",
    "table",
    "figure",
    "write",
]

#: Bird 0 of Heim et al.'s guineafowl_fit.pickle: mass [kg], leg length L [m] (their spring's rest
#: length 0.9 L plus their actuator's 0.1 L), the apex height [m] and speed [m/s], the angle of attack
#: [rad, from the vertical, the foot ahead: slipmaps' touchdown angle]; gravity [m/s^2] and the
#: stiffness [N/m] of their fit (their code, run on this pickle: 650 N/m refined to this).
BIRD = {
    "m": 1.3667,
    "l0": 0.21568925332501857,
    "k": 840.3679380231656,
    "g": 9.81,
    "apex_height": 0.19611006996014446,
    "apex_speed": 2.6622742193763442,
    "touchdown_angle": 0.5960132270021887,
}

#: Their damping values: ``constant_normalized_damping`` = d / k [s] (0.001, 0.005, 0.01 ... 0.19).
HEIM_DAMPING = (0.001, 0.005, *(round(0.01 * i, 4) for i in range(1, 20)))

#: Their ground perturbations [m] (generate_new_perturbations.py: ``np.arange(-0.07, 0.03, 0.0025)``,
#: 40 values): the ground of one step from the gait, negative a step down.
GROUNDS = tuple(round(-0.07 + 0.0025 * i, 4) for i in range(40))

#: The bounds of k_d in the gait search, as multiples of k_c (the deadbeat step's default is 0.5 ... 2).
K_D_BOUNDS = (0.5, 50.0)


@dataclass(frozen=True)
class Grid:
    """A grid: apex heights [m] and speeds [m/s] (first, last, count) and touchdown angles [deg]
    (first, last, count)."""

    heights: tuple[float, float, int]
    speeds: tuple[float, float, int]
    angles_deg: tuple[float, float, int]

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The heights, speeds [m/s] and angles [rad] as arrays."""
        h, v, a = (np.linspace(*g) for g in (self.heights, self.speeds, self.angles_deg))
        return h, v, np.radians(a)


#: Heim et al.'s grids (module docstring): 827,190 pairs.
FULL = Grid((0.05, 0.5, 91), (0.0, 10.0, 101), (0.0, 89.0, 90))
#: The reduced grid of ``--quick`` and the tests: every 5th height and speed (nearly), every 3rd angle.
QUICK = Grid((0.05, 0.5, 19), (0.0, 10.0, 21), (0.0, 87.0, 30))


@dataclass(frozen=True)
class Gait:
    """The nominal gait at one damping: the periodic apex (``apex_height`` [m], ``apex_speed`` [m/s]),
    its ``touchdown_angle`` [rad] and ``k_d`` [N/m]; ``at_bird`` whether the apex is the bird's own
    (else the lowest periodic apex found at the bird's speed); ``found`` False when none was found."""

    apex_height: float
    apex_speed: float
    touchdown_angle: float
    k_d: float
    at_bird: bool
    found: bool


def params() -> SlipParams:
    """The bird's parameters in slipmaps (k_c = k_d = their fitted stiffness, c = 0)."""
    return SlipParams(m=BIRD["m"], l0=BIRD["l0"], k=BIRD["k"], g_s=BIRD["g"], g_f=BIRD["g"])


def ratio_of(c: float, p: SlipParams) -> float:
    """The damping ratio c / (2 sqrt(k_c m)) of the leg damper ``c`` [N s/m]."""
    return c / (2.0 * math.sqrt(p.k_c * p.m))


def ratios(p: SlipParams) -> list[dict]:
    """The sweep: no damping, then each of :data:`HEIM_DAMPING` as c = (d/k) k_c, with its damping
    ratio and Heim et al.'s plot axis c / (k sqrt(l0_spring / g)) (their spring's rest length 0.9 L)."""
    out = [{"d_over_k": 0.0, "c": 0.0}]
    out += [{"d_over_k": d, "c": d * p.k_c} for d in HEIM_DAMPING]
    scale = p.k_c * math.sqrt(0.9 * p.l0 / p.g_f)
    for row in out:
        row["ratio"] = ratio_of(row["c"], p)
        row["heim_axis"] = row["c"] / scale
    return out


def _plan(p: SlipParams, h: float, v: float, angle: float):
    from ..control.deadbeat import PlanStatus, deadbeat

    bounds = {"k_d": tuple(f * p.k_c for f in K_D_BOUNDS)}
    plan = deadbeat(
        EXACT, p, h, v, h, v, controls=("touchdown_angle", "k_d"), bounds=bounds, touchdown_angle=angle
    )
    return plan if plan.status == PlanStatus.REACHED else None


def nominal_gait(p: SlipParams, top: float, step: float = 0.005, halvings: int = 12) -> Gait:
    """The periodic apex with damping ``p.c`` (module docstring): the bird's apex when the deadbeat
    step reaches it from itself, else the lowest height at the bird's speed where it does, scanned
    upward from the bird's height by ``step`` [m] up to ``top`` [m] and refined by ``halvings``
    bisections (the deadbeat step's reach grows with the height here)."""
    h0, v0, a0 = BIRD["apex_height"], BIRD["apex_speed"], BIRD["touchdown_angle"]
    plan = _plan(p, h0, v0, a0)
    if plan is not None:
        return Gait(h0, v0, plan.touchdown_angle, plan.k_d, True, True)
    low, high = h0, None
    for h in np.arange(h0 + step, top + 1e-12, step):
        if _plan(p, float(h), v0, a0) is not None:
            high = float(h)
            break
        low = float(h)
    if high is None:
        return Gait(math.nan, v0, math.nan, math.nan, False, False)
    for _ in range(halvings):
        mid = 0.5 * (low + high)
        low, high = (low, mid) if _plan(p, mid, v0, a0) is not None else (mid, high)
    plan = _plan(p, high, v0, a0)
    return Gait(high, v0, plan.touchdown_angle, plan.k_d, False, True)


def cell_measure(measure: np.ndarray, heights: np.ndarray, speeds: np.ndarray, h: float, v: float) -> float:
    """Vibly's ``interp_measure``: the mean of the measure over the grid nodes of the cell that holds
    (h, v) (``np.digitize``; the nodes inside the grid)."""
    i, j = int(np.digitize(h, heights)), int(np.digitize(v, speeds))
    nodes = [
        measure[a, b]
        for a in (i - 1, i)
        for b in (j - 1, j)
        if 0 <= a < heights.size and 0 <= b < speeds.size
    ]
    return float(np.mean(nodes)) if nodes else 0.0


def post_step(measure: np.ndarray, heights: np.ndarray, speeds: np.ndarray, p: SlipParams, gait: Gait):
    """Their figure's measure: S_M (``measure`` over ``heights`` x ``speeds``) at the apex after one
    step from the gait onto each ground of :data:`GROUNDS` (the exact map, the gait's angle and k_d
    in ``p``), looked up as their ``compute_measure_postep`` does: at the apex's height above the
    gait's ground (their state is the body's height in the world, the grid's ground 0), by
    :func:`cell_measure`; 0 where the step fails."""
    from slipmaps.generated.status import Status

    from ..api.maps import apex_return_batch

    ground = np.asarray(GROUNDS)
    res = apex_return_batch(
        EXACT, p, gait.apex_height, gait.apex_speed, gait.touchdown_angle, ground=ground, progress=False
    )
    h, v = res["next_apex_height"] + ground, res["next_apex_speed"]
    ok = (res["status"] == int(Status.OK)) & (v > 0.0)
    return [cell_measure(measure, heights, speeds, h[i], v[i]) if ok[i] else 0.0 for i in range(ground.size)]


def _row(p: SlipParams, row: dict, heights, speeds, angles) -> dict:
    """One row of :func:`measure`: the gait at damping ``row["c"]`` and its viable set."""
    start = time.perf_counter()
    pc = p.with_(c=float(row["c"]))
    gait = nominal_gait(pc, top=float(heights[-1]))
    found = {k: (None if isinstance(v, float) and math.isnan(v) else v) for k, v in asdict(gait).items()}
    out = dict(row, ratio=ratio_of(float(row["c"]), p), gait=found)  # None where no gait: JSON has no NaN
    if gait.found:
        out["k_d_over_k_c"] = gait.k_d / p.k_c
        vs = viability(
            EXACT,
            pc.with_(k_d=gait.k_d),
            apex_height=heights,
            apex_speed=speeds,
            touchdown_angle=angles,
            outside="edge",
            progress=False,
        )
        out |= {
            "viable_share": float(vs.viable.mean()),
            "viable_pairs": int(vs.viable.sum()),
            "kernel_states": int(vs.kernel.sum()),
            "safe_states": int((~vs.failed).any(axis=2).sum()),
            "measure_in_kernel": float(vs.measure[vs.kernel].mean()) if vs.kernel.any() else 0.0,
            "measure_at_gait": cell_measure(vs.measure, heights, speeds, gait.apex_height, gait.apex_speed),
            "rounds": int(vs.rounds),
        }
        after = post_step(vs.measure, heights, speeds, pc.with_(k_d=gait.k_d), gait)
        kept = [g for g, m in zip(GROUNDS, after, strict=True) if m > 0]
        out |= {
            "post_step": after,
            "post_step_mean": float(np.mean(after)),
            "post_step_grounds": [min(kept), max(kept)] if kept else None,
        }
    out["seconds"] = time.perf_counter() - start
    return out


def energy_level(grid: Grid = FULL) -> dict:
    """The undamped leg on the bird's own energy level (vibly's SLIP setting: the state is the apex
    height at the fixed flight energy m (g h + v^2/2) of the bird's apex; k_d = k_c), on the grid's
    heights and angles: the kernel's states and extent and the measure at the bird's apex (the mean
    over the two nodes about it). The control for the undamped row of the (height, speed) grid."""
    p = params()
    heights, _, angles = grid.arrays()
    energy = p.m * (p.g_f * BIRD["apex_height"] + 0.5 * BIRD["apex_speed"] ** 2)
    vs = viability(
        EXACT, p, apex_height=heights, touchdown_angle=angles, energy=energy, outside="edge", progress=False
    )
    i = int(np.digitize(BIRD["apex_height"], heights))
    on = heights[vs.kernel]
    return {
        "energy": energy,
        "kernel_states": int(vs.kernel.sum()),
        "states": int(heights.size),
        "kernel_heights": [float(on[0]), float(on[-1])] if on.size else None,
        "measure_at_bird": float(vs.measure[i - 1 : i + 1].mean()),
        "measure_in_kernel": float(vs.measure[vs.kernel].mean()) if vs.kernel.any() else 0.0,
    }


def measure(grid: Grid = FULL, sweep: list[dict] | None = None, progress: bool | None = None) -> dict:
    """The study's record (module docstring) on ``grid`` for the rows of ``sweep`` (default
    :func:`ratios`; each a dict with ``c`` [N s/m]): per row the gait, the viable share of the grid's
    pairs, the kernel, the measure at the gait's apex, the rounds and the seconds."""
    p = params()
    heights, speeds, angles = grid.arrays()
    sweep = ratios(p) if sweep is None else sweep
    rows = []
    with Bar(len(sweep), "damping viability", progress, unit="damping values") as bar:
        for row in sweep:
            rows.append(_row(p, row, heights, speeds, angles))
            bar.update(1)
    n_pairs = heights.size * speeds.size * angles.size
    return {
        "source": "Heim, Millard, Le Mouel, Badri-Sproewitz 2020 (sheim/vibly demos/damping_study)",
        "bird": dict(BIRD),
        "params": p.as_dict(),
        "grid": {**asdict(grid), "pairs": int(n_pairs)},
        "k_d_bounds_over_k_c": list(K_D_BOUNDS),
        "outside": "edge",
        "grounds": list(GROUNDS),
        "rows": rows,
        "undamped_energy_level": energy_level(grid),
    }


def table(record: dict) -> str:
    """The record as the Markdown table of docs/damping.md (one row per damping value)."""
    head = (
        "| d/k [s] | c [N s/m] | damping ratio | Heim et al.'s axis | periodic apex [m] | touchdown angle "
        "[deg] | k_d / k_c | viable share | kernel states | measure at the apex | rounds | grounds after "
        "which S_M > 0 [cm] | S_M after a step, mean |\n"
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n"
    )
    lines = []
    for r in record["rows"]:
        g = r["gait"]
        first = f"| {r['d_over_k']:g} | {r['c']:.3g} | {r['ratio']:.3g} | {r['heim_axis']:.3g} |"
        if not g["found"]:
            lines.append(f"{first} none | - | - | - | - | - | - | - | - |")
            continue
        apex = f"{g['apex_height']:.4f}" + (" (the bird's)" if g["at_bird"] else "")
        kept = r["post_step_grounds"]
        grounds = "none" if kept is None else f"{100 * kept[0]:.2f} ... {100 * kept[1]:.2f}"
        lines.append(
            f"{first} {apex} | {math.degrees(g['touchdown_angle']):.1f} | {r['k_d_over_k_c']:.3g} | "
            f"{r['viable_share']:.4f} | {r['kernel_states']:,} | {r['measure_at_gait']:.3f} | "
            f"{r['rounds']} | {grounds} | {r['post_step_mean']:.3f} |"
        )
    return head + "\n".join(lines) + "\n"


def figure(record: dict, path) -> Path:
    """The measure against the damping ratio, and the gait's k_d / k_c, into ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..api.paths import save_figure

    rows = [r for r in record["rows"] if r["gait"]["found"]]
    zeta = np.array([r["ratio"] for r in rows])
    bird = np.array([r["gait"]["at_bird"] for r in rows], dtype=bool)
    fig, (ax, kd, after) = plt.subplots(1, 3, figsize=(15, 4), constrained_layout=True)
    share = np.array([r["viable_share"] for r in rows])
    at_gait = np.array([r["measure_at_gait"] for r in rows])
    ax.plot(zeta, share, "o-", label="viable share of the grid's pairs")
    ax.plot(zeta, at_gait, "s--", label="measure at the gait's apex")
    ax.plot(zeta[~bird], share[~bird], "o", mfc="w", color="C0", label="gait above the bird's apex")
    level = record["undamped_energy_level"]["measure_at_bird"]
    ax.plot(
        [0.0], [level], "D", color="C1", mfc="w", label="undamped, on the bird's energy level: at its apex"
    )
    none = [r["ratio"] for r in record["rows"] if not r["gait"]["found"]]
    if none:
        ax.axvspan(min(none), max(none), color="0.85", label="no periodic gait")
    ax.set_xlabel("damping ratio c / (2 sqrt(k m))")
    ax.set_ylabel("share of state-action pairs / of angles")
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    g = record["grid"]
    ax.set_title(
        f"bird 0, exact map, {g['heights'][2]} x {g['speeds'][2]} states x {g['angles_deg'][2]} angles"
    )
    kd.plot(zeta, [r["k_d_over_k_c"] for r in rows], "o-", color="C2")
    kd.axhline(record["k_d_bounds_over_k_c"][1], color="C2", ls=":", lw=1)
    kd.set_xlabel("damping ratio c / (2 sqrt(k m))")
    kd.set_ylabel("k_d / k_c of the periodic gait", color="C2")
    h = kd.twinx()
    h.plot(zeta, [r["gait"]["apex_height"] for r in rows], "s--", color="C3")
    h.set_ylabel("the gait's apex height [m]", color="C3")
    grounds = 100 * np.asarray(record["grounds"])
    mesh = after.pcolormesh(
        grounds,
        np.arange(zeta.size),
        [r["post_step"] for r in rows],
        shading="nearest",
        vmin=0,
        cmap="viridis",
    )
    after.set_yticks(np.arange(zeta.size)[::2], [f"{z:.2g}" for z in zeta[::2]])
    after.set_xlabel("ground of one step from the gait [cm] (negative: down)")
    after.set_ylabel("damping ratio")
    after.set_title("S_M at the apex after that step")
    fig.colorbar(mesh, ax=after)
    save_figure(fig, path)
    return Path(path)


def write(out, quick: bool = False, progress: bool | None = None) -> list[Path]:
    """Measure the study (``quick``: :data:`QUICK` and every 4th row of the sweep) and write
    damping_viability.json and .png into ``out``; the paths written."""
    out = Path(out)
    sweep = ratios(params())
    record = measure(QUICK if quick else FULL, sweep[::4] if quick else sweep, progress)
    path = out / "damping_viability.json"
    path.write_text(json.dumps(record, indent=1, allow_nan=False) + "\n", encoding="utf-8")
    return [path, figure(record, out / "damping_viability.png")]
