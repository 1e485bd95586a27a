"""Claims on the stance maps' accuracy, measured (docs/reproductions.json; :mod:`.reproductions`
adds the verdicts, :mod:`.reproductions_report` renders them).

Conventions (docs/conventions.md): SI units; the leg angle q_th from the vertical, counterclockwise
positive; the papers' angle of attack from the ground alpha0 = 90 deg - q_th_td. Every map runs at
its defaults; "exact" is the compiled exact simulator (DOP853, rtol 1e-11).

* :func:`measure_geyer`: Geyer, Seyfarth and Blickhan 2005: map ``geyer``'s stance against the exact
  one from the same touchdown, q_r and q_th at :data:`GEYER_SAMPLES` equispaced times on
  [0, min(t_stance)] (both still in stance), on two settings of :data:`GEYER_SETTINGS`; one row of
  :data:`GEYER_COLUMNS` per state.
* :func:`measure_yu`: Yu, Li and Cai 2012: the next-apex error |(dh, dv)|/|(h, v)| of the accuracy
  study (:func:`.accuracy.apex_errors`, the exact steps by the compiled batches,
  :func:`.accuracy.run_batch`) of the gravity corrections, ``geyer`` and ``iterative`` on the whole
  protocol :data:`YU_GRID` (6765 states); the states whose exact step fails are counted and left out.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..analysis.gait import fixed_points
from ..api import index, model
from ..api.calls import Call
from ..api.maps import stance, touchdown_inputs
from ..api.params import SlipParams
from ..api.progress import progress
from .accuracy import Variant, apex_errors, compared, exact_failures, map_failures, run_batch
from .grids import YU_PARAMS, Grid, equispaced

__all__ = [
    "GEYER_TOL",
    "GEYER_DOMAIN",
    "GEYER_COLUMNS",
    "GEYER_SETTINGS",
    "YU_GRID",
    "YU_TARGET",
    "source",
    "stance_errors",
    "geyer_states",
    "geyer_rows",
    "measure_geyer",
    "yu_maps",
    "yu_record",
    "measure_yu",
]

# ---- Geyer, Seyfarth and Blickhan 2005 ---------------------------------------------------------
#: Tolerances of the abstract: q_r error / l0, q_th error [deg].
GEYER_TOL = {"q_r": 0.01, "q_th_deg": 0.6}
#: Its domain: exact bottom compression (l0 - q_r_b)/l0, angle of attack [deg], exact sweep [deg].
GEYER_DOMAIN = {"compression": 0.20, "attack_deg": 60.0, "sweep_deg": 60.0}
GEYER_STIFFNESS = (10e3, 15e3, 20e3, 25e3, 30e3)  # N/m, the human runner's m and l0
GEYER_HEIGHTS = (1.0, 1.05, 1.1)
GEYER_SPEEDS = equispaced(3.0, 1.0, 6)
GEYER_ATTACK = equispaced(56.0, 2.0, 13)
#: Times compared per stance: equispaced on [0, the earlier of the two liftoffs].
GEYER_SAMPLES = 50
#: The columns of a stance row: the state (stiffness, apex), the exact stance's compression and
#: sweep, the largest |q_r error| / l0, |q_r error| / exact compression and |q_th error| [deg].
GEYER_COLUMNS = (
    "k",
    "apex_height",
    "apex_speed",
    "attack_deg",
    "compression",
    "sweep_deg",
    "q_r_error",
    "q_r_error_of_compression",
    "q_th_error_deg",
)

# ---- Yu, Li and Cai 2012 -----------------------------------------------------------------------
YU_ATTACK = equispaced(60.0, 1.0, 15)
YU_GRID = Grid(
    "Yu, Li and Cai protocol, whole",
    "yu",
    YU_PARAMS,
    heights=equispaced(0.95, 0.01, 11),
    speeds=equispaced(2.0, 0.1, 41),
    angles=tuple(round(math.radians(90.0 - a), 12) for a in YU_ATTACK),
    description="m = 80 kg, l0 = 1 m, k = 7848 N/m (k l0/(m g) = 10); apex height 0.95-1.05 m (11), apex "
    "speed 2-6 m/s (41), angle of attack 60-74 deg (15, step 1 deg): 6765 states",
)
YU_TARGET = {"mean": 0.05, "max": 0.15}


def source(authors: str, title: str, venue: str, year) -> dict:
    """A claim's source: authors, title ("" when not given), venue, year (None: an online text)."""
    return {"authors": authors, "title": title, "venue": venue, "year": year}


# ----------------------------------------------------------------------------------------------
# 1. Geyer et al.: the stance trajectory
# ----------------------------------------------------------------------------------------------
def _states_at(call: Call, touchdown, times: np.ndarray) -> np.ndarray:
    """The map's polar state at ``times`` after touchdown (its ``state_at`` kernel, row by row: one
    batch per stance would cost a thread launch for 50 rows)."""
    fixed = touchdown_inputs(call, touchdown)
    return np.array([call.scalar("state_at", {**fixed, "t": float(t)})[1] for t in times])


def stance_errors(params: SlipParams, touchdown, samples: int = GEYER_SAMPLES) -> dict | None:
    """``geyer`` against the exact stance from ``touchdown``: the exact compression (l0 - q_r_b)/l0
    and sweep |q_th_lo - q_th_td| [deg], and the largest errors over ``samples`` equispaced times
    on [0, min(t_stance)] (both in stance); None when either stance fails."""
    ex, gy = stance(index.EXACT, params, touchdown), stance("geyer", params, touchdown)
    if not (ex.ok and gy.ok):
        return None
    times = np.linspace(0.0, min(ex.t_stance, gy.t_stance), samples)
    se = _states_at(Call.of(index.EXACT, params, {}), touchdown, times)
    sg = _states_at(Call.of("geyer", params, {}), touchdown, times)
    compression = (params.l0 - ex.bottom_q_r) / params.l0
    dr = float(np.max(np.abs(sg[:, 0] - se[:, 0])))
    return {
        "compression": compression,
        "sweep_deg": math.degrees(abs(ex.liftoff_q_th - touchdown[2])),
        "q_r_error": dr / params.l0,
        "q_r_error_of_compression": dr / (params.l0 - ex.bottom_q_r),
        "q_th_error_deg": math.degrees(float(np.max(np.abs(sg[:, 2] - se[:, 2])))),
    }


def geyer_states(setting: str, stiffness: Sequence[float] = GEYER_STIFFNESS) -> list[tuple[float, ...]]:
    """(k, apex height, apex speed, q_th_td) of a setting: ``"grid"`` every angle of attack of
    :data:`GEYER_ATTACK`; ``"periodic"`` the touchdown angles of the exact periodic gaits (the
    fixed points of each apex; their stance is symmetric)."""
    out = []
    for k in stiffness:
        p = SlipParams(k=k)
        for h in GEYER_HEIGHTS:
            for v in GEYER_SPEEDS:
                if setting == "grid":
                    out += [(k, h, v, round(math.radians(90.0 - a), 12)) for a in GEYER_ATTACK]
                else:
                    out += [
                        (k, h, v, f.touchdown_angle)
                        for f in fixed_points(index.EXACT, p, apex_height=h, speed=v)
                        if f.ok
                    ]
    return out


def geyer_rows(states, show_progress: bool | None = None, label: str = "") -> tuple[list[list[float]], int]:
    """A :data:`GEYER_COLUMNS` row per state whose two stances complete, and the count of the others."""
    rows, failed = [], 0
    for k, h, v, th in progress(states, len(states), f"Geyer et al. 2005 {label}".strip(), show_progress):
        p = SlipParams(k=k)
        status, td = model.call(
            "apex_to_touchdown", b_y_apex=h, b_xd_apex=v, q_th_td=th, q_r_td=p.q_r_td, g_f=p.g_f, ground=0.0
        )
        state = tuple(td[f"touchdown_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd"))
        err = stance_errors(p, state) if status == 0 else None
        if err is None:
            failed += 1
            continue
        rows.append([k, h, v, 90.0 - math.degrees(th), *(err[c] for c in GEYER_COLUMNS[4:])])
    return rows, failed


#: The two settings measured: name -> (label, description).
GEYER_SETTINGS = {
    "periodic": (
        "periodic gaits",
        "the exact periodic gaits: for every stiffness k = 10, 15, 20, 25, 30 kN/m (m = 80 kg, l0 = 1 m), "
        "apex height 1.0, 1.05, 1.1 m and apex speed 3-8 m/s, each touchdown angle whose exact step "
        "returns to the same apex (its stance is symmetric)",
    ),
    "grid": (
        "every touchdown of the grid",
        "the same stiffnesses, apex heights and speeds, angles of attack 56-80 deg (step 2 deg); most "
        "stances are nonsymmetric",
    ),
}


def measure_geyer(show_progress: bool | None = None) -> dict:
    settings = []
    for name, (label, text) in GEYER_SETTINGS.items():
        rows, failed = geyer_rows(geyer_states(name), show_progress, label)
        settings.append({"name": name, "label": label, "description": text, "rows": rows, "failed": failed})
    return {
        "source": source(
            "Geyer, Seyfarth and Blickhan",
            "Spring-mass running: simple approximate solution and application to gait stability",
            "J Theor Biol 232, 315-328",
            2005,
        ),
        "claim": "for spring compressions up to 20 % (angle of attack >= 60 deg, angular sweep <= 60 deg) "
        "the approximate solution describes the stance within a 1 % tolerance of spring compression and "
        "0.6 deg of angular motion compared to numerical calculations",
        "paper": {"tolerance": GEYER_TOL, "domain": GEYER_DOMAIN},
        "columns": list(GEYER_COLUMNS),
        "samples": GEYER_SAMPLES,
        "settings": settings,
    }


# ----------------------------------------------------------------------------------------------
# 2. Yu, Li and Cai: next-apex error on the whole protocol
# ----------------------------------------------------------------------------------------------
def yu_maps() -> list[str]:
    """The gravity corrections (role "yu-target") and, for reference, Geyer et al.'s and the
    converging iterative map."""
    return [m.name for m in index.maps() if "yu-target" in m.roles] + ["geyer", "iterative"]


def yu_record(grid: Grid, names: Sequence[str]) -> dict:
    """The exact failures, and per map: compared states, map failures, the next-apex error's mean and
    max over the compared states, and the same per angle of attack."""
    points = grid.points()
    run = run_batch(grid, points, [Variant(n) for n in names])
    attack = np.round(90.0 - np.degrees(points[:, 2]), 9)
    maps = []
    for n in names:
        err, ok = apex_errors(run, n), compared(run, n)
        by_angle = [
            {
                "attack_deg": float(a),
                "n": int(ok[attack == a].sum()),
                "mean": float(np.mean(err[ok & (attack == a)])),
                "max": float(np.max(err[ok & (attack == a)])),
            }
            for a in np.unique(attack)
            if (ok & (attack == a)).any()
        ]
        maps.append(
            {
                "map": n,
                "compared": int(ok.sum()),
                "map_failures": dict(sorted(map_failures(run, n).items())),
                "mean": float(np.mean(err[ok])),
                "max": float(np.max(err[ok])),
                "by_angle": by_angle,
            }
        )
    return {
        "states": len(points),
        "exact_ok": int((run.exact_status == 0).sum()),
        "exact_failures": exact_failures(run),
        "maps": maps,
    }


def measure_yu(show_progress: bool | None = None) -> dict:
    return {
        "source": source("Yu, Li and Cai", "", "IEEE ICRA", 2012),
        "claim": "their gravity-corrected approximation of the stance predicts the next apex within a "
        "mean relative error below 5 % and a maximum below 15 % over about 6,500 states",
        "paper": {**YU_TARGET, "states": 6500},
        "setting": {"params": YU_GRID.params.as_dict(), "description": YU_GRID.description},
        **yu_record(YU_GRID, yu_maps()),
    }
