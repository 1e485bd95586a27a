"""Claims on periodic gaits, measured (docs/reproductions.json; :mod:`.reproductions` adds the
verdicts, :mod:`.reproductions_report` renders them).

Conventions (docs/conventions.md): SI units; the leg angle q_th from the vertical, counterclockwise
positive; the angle of attack from the ground alpha0 = 90 deg - q_th_td; the dimensionless
stiffness k l0/(m g) and energy E/(m g l0). Fixed points are :func:`.gait.fixed_points` on an energy
level at a fixed touchdown angle (the unknown: the apex height), for the exact map and every
approximate map at its defaults (:func:`approximate_maps`).

* :func:`measure_seyfarth`: Seyfarth et al. 2002 / 2003: the human runner at the energy of 5 m/s at
  apex height 1 m and alpha0 = 68 deg; the fixed points, and the return map h_i -> h_{i+1} on
  :data:`SEYFARTH_HEIGHTS` of the exact map and the maps with the role "region".
* :func:`measure_drake`: the SLIP notebook of Tedrake's Underactuated Robotics (m = 80 kg, l0 = 1 m,
  q_th_td = 30 deg, E/(m g l0) = 1.61): the fixed points at k l0/(m g) = 10.7 and 10.8, and over
  :data:`KAPPAS`, with the stiffness ranges with a fixed point and with a stable one (the scan's
  runs, each end bisected to :data:`KAPPA_TOL`; a scan end stays itself).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..analysis.gait import fixed_points
from ..api import index
from ..api.maps import apex_return_batch
from ..api.params import HUMAN_RUNNER, SlipParams
from ..api.progress import progress
from .grids import equispaced
from .reproductions_stance import source
from .stability import energy_at_rest_height

__all__ = [
    "SEYFARTH",
    "SEYFARTH_HEIGHTS",
    "DRAKE",
    "KAPPAS",
    "KAPPA_TOL",
    "G",
    "approximate_maps",
    "point_rows",
    "measure_seyfarth",
    "drake_params",
    "drake_points",
    "has_fixed_points",
    "measure_drake",
]

#: Gravity of the notebook [m/s^2].
G = 9.81
# ---- Seyfarth et al. 2002 / 2003 and the Underactuated notebook ---------------------------------
SEYFARTH = {"speed": 5.0, "attack_deg": 68.0}
#: The apex heights [m] of the return map drawn: from just above the touchdown height l0 cos 22 deg.
SEYFARTH_HEIGHTS = equispaced(0.928, 0.002, 262)
DRAKE = {"kappa": 10.7, "kappa_figure": 10.8, "energy": 1.61, "angle_deg": 30.0}
#: The dimensionless stiffnesses scanned (every 0.5 to 10, every 0.05 to 12), then bisected to
#: KAPPA_TOL at every change of the scan.
KAPPAS = equispaced(3.0, 0.5, 14) + equispaced(10.0, 0.05, 41)
KAPPA_TOL = 1e-4


def approximate_maps() -> list[str]:
    """Every map of the index but the exact one, in index order."""
    return [m.name for m in index.maps() if m.name != index.EXACT]


# ----------------------------------------------------------------------------------------------
# 3. Seyfarth et al.: a stable fixed point at 68 deg; 4. the notebook's 10.7 and 10.8
# ----------------------------------------------------------------------------------------------
def point_rows(points) -> list[dict]:
    """The fixed points' apex height [m], speed [m/s], eigenvalue and status."""
    return [
        {
            "apex_height": p.apex_height,
            "apex_speed": p.apex_speed,
            "eigenvalue": p.eigenvalue,
            "status": p.status.name,
        }
        for p in points
    ]


def measure_seyfarth(show_progress: bool | None = None, names: Sequence[str] | None = None) -> dict:
    p = HUMAN_RUNNER
    energy = energy_at_rest_height(p, SEYFARTH["speed"])
    angle = round(math.radians(90.0 - SEYFARTH["attack_deg"]), 12)
    names = [index.EXACT, *approximate_maps()] if names is None else list(names)
    h = np.array(SEYFARTH_HEIGHTS)
    v = np.sqrt(2.0 * (energy / p.m - p.g_f * h))
    shown = [index.EXACT, *(m.name for m in index.maps() if "region" in m.roles)]
    return {
        "source": [
            source(
                "Seyfarth, Geyer, Guenther and Blickhan",
                "A movement criterion for running",
                "J Biomech 35, 649-655",
                2002,
            ),
            source(
                "Seyfarth, Geyer and Herr",
                "Swing-leg retraction: a simple control model for stable running",
                "J Exp Biol 206, 2547-2555",
                2003,
            ),
        ],
        "claim": "the human runner (80 kg, 1 m, 20 kN/m) at the energy of 5 m/s at apex height 1 m with a "
        "fixed angle of attack of 68 deg has a stable fixed point of its apex-height return map",
        "paper": {"speed": SEYFARTH["speed"], "apex_height": p.l0, "attack_deg": SEYFARTH["attack_deg"]},
        "setting": {"params": p.as_dict(), "energy": energy, "touchdown_angle": angle},
        "fixed_points": {n: point_rows(fixed_points(n, p, energy=energy, angle=angle)) for n in names},
        "return_map": {
            "heights": list(SEYFARTH_HEIGHTS),
            "next": {n: apex_return_batch(n, p, h, v, angle)["next_apex_height"].tolist() for n in shown},
        },
    }


def drake_params(kappa: float) -> SlipParams:
    """m = 80 kg, l0 = 1 m, g = 9.81 m/s^2 and k = kappa m g / l0 (the notebook's)."""
    return SlipParams(m=80.0, l0=1.0, k=kappa * 80.0 * G / 1.0, g_s=G, g_f=G)


def drake_points(name: str, kappa: float) -> list[dict]:
    """The completed fixed points (:func:`point_rows`) of map ``name`` on the notebook's line at
    stiffness ``kappa``."""
    p = drake_params(kappa)
    found = fixed_points(
        name, p, energy=DRAKE["energy"] * p.m * G * p.l0, angle=math.radians(DRAKE["angle_deg"])
    )
    return [r for r in point_rows(found) if r["status"] == "OK"]


def has_fixed_points(points: list[dict]) -> tuple[bool, bool]:
    """Whether completed fixed points ``points`` (:func:`drake_points`) are there, and a stable one."""
    return bool(points), any(abs(r["eigenvalue"]) < 1.0 for r in points)


def _ranges(name: str, scan: list[dict], which: int) -> list[list[float]]:
    """The intervals of the stiffness with a fixed point (``which`` 0) or a stable one (1): the scan's
    runs, each end bisected to KAPPA_TOL between its two scan points (a scan end stays itself)."""
    flags = [has_fixed_points(s["fixed_points"])[which] for s in scan]
    kappas = [s["kappa"] for s in scan]

    def edge(a: float, b: float) -> float:  # has(a) != has(b)
        fa = has_fixed_points(drake_points(name, a))[which]
        while b - a > KAPPA_TOL:
            mid = 0.5 * (a + b)
            if has_fixed_points(drake_points(name, mid))[which] == fa:
                a = mid
            else:
                b = mid
        return 0.5 * (a + b)

    out, start = [], None
    for i, f in enumerate(flags):
        if f and start is None:
            start = kappas[0] if i == 0 else edge(kappas[i - 1], kappas[i])
        if start is not None and (not f or i == len(flags) - 1):
            out.append([start, kappas[i] if f else edge(kappas[i - 1], kappas[i])])
            start = None
    return out


def measure_drake(
    show_progress: bool | None = None, names: Sequence[str] | None = None, kappas: Sequence[float] = KAPPAS
) -> dict:
    names = [index.EXACT, *approximate_maps()] if names is None else list(names)
    subjects = {}
    for n in progress(names, len(names), "Underactuated SLIP notebook: stiffness scans", show_progress):
        scan = [{"kappa": k, "fixed_points": drake_points(n, k)} for k in kappas]
        subjects[n] = {
            "at": {str(k): drake_points(n, k) for k in (DRAKE["kappa"], DRAKE["kappa_figure"])},
            "scan": scan,
            "exists": _ranges(n, scan, 0),
            "stable": _ranges(n, scan, 1),
        }
    return {
        "source": source(
            "Tedrake",
            "Underactuated Robotics: Algorithms for Walking, Running, Swimming, Flying, and Manipulation, "
            "chapter Simple Models of Walking and Running, its SLIP notebook",
            "online course notes, MIT; the notebook book/simple_legs/slip.ipynb of "
            "RussTedrake/underactuated, read at commit 1d4923e",
            None,
        ),
        "claim": "with the parameters of Geyer05 (m 80 kg, l0 1 m; the notebook cites its section 2.4.3 and "
        "figure 2.4), the leg at 30 deg from the vertical at touchdown and E/(m g l0) = 1.61, the "
        "apex-to-apex map has fixed points at k l0/(m g) = 10.7; with the 10.8 of Geyer05's figure the "
        "notebook finds none",
        "paper": dict(DRAKE),
        "setting": {"kappas": list(kappas), "kappa_tol": KAPPA_TOL},
        "subjects": subjects,
    }
