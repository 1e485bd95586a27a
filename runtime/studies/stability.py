"""The periodic-gait study (measurements): each map's fixed points and eigenvalues against the exact
ones, and the self-stable region. ``slipmaps accuracy`` writes docs/stability.json, .md, .png from
it (:func:`measure` is the record; :class:`.stability_report.StabilityStudy` renders it, through
:mod:`.study`).

* Fixed points (:data:`GRIDS`, small: the exact simulator finds each line's fixed points in about
  0.2-0.5 s with ``solve_ivp``): on every line of every grid, :func:`.gait.fixed_points` of the
  exact map and of every approximate map at its defaults (all of them accept k_c == k_d).
* Self-stable region (:data:`REGION_SPEEDS` x :data:`REGION_AOA`, the maps of :func:`region_maps`:
  the exact one and every map with the role "region" in the index):
  Seyfarth et al.'s setting (J Biomech 35 (2002) 649-655): the human runner, the system energy
  given as the speed v0 at apex height l0 (E = m (g_f l0 + v0^2/2)) and the angle of attack from the
  ground alpha0 = 90 deg - q_th_td; every fixed point of the apex height on that energy level, the
  cell classed by :func:`cell_class`. The grid is sized for the compiled exact simulator (2701
  cells, a few hundred exact steps each); with ``solve_ivp`` it takes about 20 minutes.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from ..analysis.gait import FixedPoint, fixed_points
from ..api import index
from ..api.index import EXACT
from ..api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from ..api.progress import progress
from . import study as pipeline
from .grids import equispaced

__all__ = [
    "GRIDS",
    "REGION_SPEEDS",
    "REGION_AOA",
    "REGION_ROLE",
    "GaitGrid",
    "energy_at_rest_height",
    "cell_class",
    "point_record",
    "measure_grid",
    "measure_region",
    "region_maps",
    "region_record",
    "measure",
    "from_json",
]

#: Speeds v0 [m/s] at apex height l0 that set the energy of the region's rows ...
REGION_SPEEDS = equispaced(2.0, 0.25, 37)
#: ... and its angles of attack alpha0 = 90 deg - q_th_td [deg].
REGION_AOA = equispaced(44.0, 0.5, 73)
#: The role (``MapInfo.roles``) of the maps of the region figure, beside the exact one (Geyer et
#: al.'s, the best gravity correction and the converging iterative map).
REGION_ROLE = "region"


def energy_at_rest_height(params: SlipParams, v0: float) -> float:
    """The energy [J] of an apex at height l0 with speed v0: m (g_f l0 + v0^2/2)."""
    return params.m * (params.g_f * params.l0 + 0.5 * v0**2)


@dataclass(frozen=True)
class GaitGrid:
    """Lines on which fixed points are searched: ``kind`` "angle" (each line an apex height and speed,
    the touchdown angle unknown) or "height" (an energy and a touchdown angle, the apex height
    unknown)."""

    name: str
    kind: str
    params: SlipParams
    lines: tuple[dict, ...]  # keyword arguments of fixed_points
    description: str

    @property
    def unknown(self) -> str:
        return "touchdown_angle" if self.kind == "angle" else "apex_height"


def _aoa_line(params: SlipParams, v0: float, aoa: float) -> dict:
    return {"energy": energy_at_rest_height(params, v0), "angle": round(math.radians(90.0 - aoa), 12)}


#: The fixed-point accuracy grids: the human runner at apex height l0, the robot hopper at the same
#: Froude numbers, and Seyfarth et al.'s energy of 5 m/s at 1 m over angles of attack.
GRIDS: tuple[GaitGrid, ...] = (
    GaitGrid(
        "human runner, apex height 1 m",
        "angle",
        HUMAN_RUNNER,
        tuple({"apex_height": 1.0, "speed": v} for v in equispaced(3.0, 1.0, 5)),
        "apex height 1 m, apex speeds 3-7 m/s; the unknown is the touchdown angle",
    ),
    GaitGrid(
        "robot hopper, apex height l0",
        "angle",
        ROBOT_HOPPER,
        tuple({"apex_height": ROBOT_HOPPER.l0, "speed": v} for v in equispaced(1.5, 0.5, 5)),
        "apex height l0 = 0.25 m, apex speeds 1.5-3.5 m/s (the human runner's Froude numbers); the "
        "unknown is the touchdown angle",
    ),
    GaitGrid(
        "human runner, energy of 5 m/s at 1 m",
        "height",
        HUMAN_RUNNER,
        tuple(_aoa_line(HUMAN_RUNNER, 5.0, a) for a in (67.0, 68.0, 69.0, 70.0, 72.0)),
        "Seyfarth et al.'s energy (5 m/s at apex height 1 m), angles of attack 67, 68, 69, 70, 72 deg "
        "from the ground; the unknown is the apex height",
    ),
)


def point_record(p: FixedPoint) -> dict:
    """The recorded numbers of a fixed point: the apex, the eigenvalue, the Floquet multipliers (the
    distance of the one nearest 1 from 1, recorded before rounding, and the other as [re, im]), the
    residuals and the status."""
    d = p.as_dict()
    keys = ("apex_height", "apex_speed", "touchdown_angle", "eigenvalue", "residual", "speed_residual")
    out = {k: d[k] for k in keys}
    out["energy_multiplier_deviation"] = float(abs(p.multipliers[0] - 1.0))
    out["multiplier"] = d["multipliers"][1]
    out["status"] = d["status"]
    return out


def measure_grid(grid: GaitGrid, names: Sequence[str], show_progress: bool | None = None) -> dict:
    """Every line's fixed points by the exact map and by each map of ``names``."""
    lines = []
    for line in progress(grid.lines, len(grid.lines), f"fixed points ({grid.name})", show_progress):
        lines.append(
            {
                "given": dict(line),
                "exact": [point_record(p) for p in fixed_points(EXACT, grid.params, **line)],
                "maps": {n: [point_record(p) for p in fixed_points(n, grid.params, **line)] for n in names},
            }
        )
    return {
        "name": grid.name,
        "kind": grid.kind,
        "unknown": grid.unknown,
        "description": grid.description,
        "params": grid.params.as_dict(),
        "lines": lines,
    }


def cell_class(points: Sequence[FixedPoint]) -> str:
    """A region cell: ``S`` a self-stable fixed point (|eigenvalue| < 1), ``u`` fixed points, none
    stable, ``!`` only fixed points whose refinement failed, ``.`` none."""
    if any(p.stable for p in points):
        return "S"
    if any(p.ok for p in points):
        return "u"
    return "!" if points else "."


def measure_region(
    name: str,
    params: SlipParams = HUMAN_RUNNER,
    speeds: Sequence[float] = REGION_SPEEDS,
    aoas: Sequence[float] = REGION_AOA,
    show_progress: bool | None = None,
) -> dict:
    """The region of map ``name``: per speed v0 a string of cell classes over the angles of attack and
    the smallest |eigenvalue| of each cell's fixed points (None where there is none)."""
    cells = [(v, a) for v in speeds for a in aoas]
    found = {}
    for v, a in progress(cells, len(cells), f"stability region ({name})", show_progress):
        found[v, a] = fixed_points(name, params, **_aoa_line(params, v, a))
    classes, eig = [], []
    for v in speeds:
        classes.append("".join(cell_class(found[v, a]) for a in aoas))
        eig.append([min((abs(p.eigenvalue) for p in found[v, a] if p.ok), default=math.nan) for a in aoas])
    return {"classes": classes, "min_abs_eigenvalue": eig}


def region_maps(map_names: Sequence[str] | None = None) -> list[str]:
    """The maps of the region: the exact one and, all maps measured, every map with the role
    :data:`REGION_ROLE` (index order), else ``map_names``."""
    if map_names is None:
        return [EXACT, *(m.name for m in index.maps() if REGION_ROLE in m.roles)]
    return [EXACT, *(n for n in map_names if n != EXACT)]


def region_record(names: Sequence[str], show_progress: bool | None = None) -> dict:
    """The region of each map of ``names`` on the human runner's grid, with the grid."""
    return {
        "params": HUMAN_RUNNER.as_dict(),
        "speeds": list(REGION_SPEEDS),
        "angles_of_attack_deg": list(REGION_AOA),
        "maps": {n: measure_region(n, show_progress=show_progress) for n in names},
    }


def measure(
    map_names: Sequence[str] | None = None,
    region: Sequence[str] | None = None,
    show_progress: bool | None = None,
) -> dict:
    """The record: fixed points of every approximate map of ``map_names`` (default all) on
    :data:`GRIDS`, and the region of the maps ``region`` (default :func:`region_maps`)."""
    names = [m.name for m in index.maps() if m.name != EXACT] if map_names is None else list(map_names)
    names = [n for n in names if n != EXACT]
    chosen = region_maps(map_names) if region is None else list(region)
    return {
        "grids": [measure_grid(g, names, show_progress) for g in GRIDS],
        "region": region_record(chosen, show_progress),
    }


def from_json(text: str) -> dict:
    """The record of docs/stability.json: ``grids`` and ``region``."""
    data = pipeline.from_json(text)
    return {"grids": data["grids"], "region": data["region"]}
