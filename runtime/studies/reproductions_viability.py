"""Heim and Spröwitz's SLIP viable set, measured (docs/reproductions.json, claim ``heim``;
:mod:`.reproductions` adds the verdict, :mod:`.reproductions_report` renders it).

Vibly's SLIP demo (sheim/vibly, demos/computeQ_slip.py): m = 80 kg, k = 8200 N/m, l0 = 1 m,
g = 9.81 m/s^2, the flight energy 1877.08 J, the state s = m g y / E on 180 points in [0.1, 0.995],
the angle of attack from the vertical on -10 ... 70 deg in 161 steps (vibly's angle is slipmaps'
touchdown angle). The published numbers (:data:`VIBLY`) are read from vibly's published arrays
(tests/integration/data/slip_map.npz of sheim/vibly, kept as tests/data/vibly_slip_map.npz;
tests/test_reproductions.py checks them against that file): the sizes of the failure set Q_F and of
the viable set Q_V, the kernel's states, the measure S_M's peak and its value at the top state, and a
fingerprint of Q_F and of Q_V (:func:`fingerprint`), so that the record states "pair for pair".

:func:`measure_heim` computes the same sets with ``slipmaps.viability`` on the exact map with vibly's
rule for a next state beyond the grid (``outside="edge"``), records the same numbers, and the shape
of the set: per state the viable angles' range, the measure, and the state-action plane as text (one
string per state, one character per angle: ``x`` the step fails, ``o`` it completes but leaves the
kernel, ``v`` viable). The default rule (``outside="fail"``) is recorded beside it.
"""

from __future__ import annotations

import hashlib

import numpy as np

from ..analysis.viability import viability
from ..api.index import EXACT
from ..api.params import SlipParams
from ..api.progress import progress
from .reproductions_stance import source

__all__ = ["HEIM", "VIBLY", "fingerprint", "vibly_grid", "set_numbers", "measure_heim"]

#: The demo's setting: parameters, flight energy [J], the s grid (first, last, count: vibly's
#: ``np.linspace(0.1, 1, 181)[:-1]``) and the angle grid [deg] (first, last, count).
HEIM = {
    "m": 80.0,
    "k": 8200.0,
    "l0": 1.0,
    "g": 9.81,
    "energy": 1877.08,
    "s": [0.1, 0.995, 180],
    "angle_deg": [-10.0, 70.0, 161],
}

#: Vibly's published arrays in numbers (tests/data/vibly_slip_map.npz; tests/test_reproductions.py).
VIBLY = {
    "pairs": 28980,
    "failed_pairs": 23909,
    "viable_pairs": 5066,
    "kernel_states": 170,
    "measure_max": 0.285714,
    "measure_max_s": 0.365,
    "measure_top": 0.124224,
    "failed_fingerprint": "43ec1a8a607f5131",
    "viable_fingerprint": "61ee37f2e4c345da",
}


def fingerprint(pairs: np.ndarray) -> str:
    """The first 16 hex digits of the SHA-256 of a boolean state x action array's bits (C order):
    equal fingerprints mean the same set, pair for pair."""
    bits = np.packbits(np.ascontiguousarray(pairs, dtype=bool).ravel())
    return hashlib.sha256(bits.tobytes()).hexdigest()[:16]


def vibly_grid() -> tuple[SlipParams, np.ndarray, np.ndarray, np.ndarray]:
    """The parameters, vibly's s grid, the apex heights h = s E / (m g) [m] and the angles [rad]."""
    p = SlipParams(m=HEIM["m"], l0=HEIM["l0"], k=HEIM["k"], g_s=HEIM["g"], g_f=HEIM["g"])
    s = np.linspace(0.1, 1, 181)[:-1]
    heights = s * HEIM["energy"] / (p.m * p.g_f)
    angles = np.linspace(-10 / 180 * np.pi, 70 / 180 * np.pi, 161)  # vibly's, to the last bit
    return p, s, heights, angles


def set_numbers(vs, s: np.ndarray) -> dict:
    """The numbers of :data:`VIBLY` for a viable set ``vs`` on the s grid ``s``."""
    peak = int(np.argmax(vs.measure))
    return {
        "pairs": int(vs.failed.size),
        "failed_pairs": int(vs.failed.sum()),
        "viable_pairs": int(vs.viable.sum()),
        "kernel_states": int(vs.kernel.sum()),
        "measure_max": float(vs.measure[peak]),
        "measure_max_s": float(s[peak]),
        "measure_top": float(vs.measure[-1]),
        "failed_fingerprint": fingerprint(vs.failed),
        "viable_fingerprint": fingerprint(vs.viable),
    }


def _shape(vs, s: np.ndarray, heights: np.ndarray, angles_deg: np.ndarray) -> dict:
    """Per state the viable angles' first and last (None: none), the measure and the plane as text;
    the kernel's extent in s and h, the band's width over the kernel (median, 10th, 90th percentile)."""
    lo, hi, rows = [], [], []
    for i in range(s.size):
        ok = np.flatnonzero(vs.viable[i])
        lo.append(float(angles_deg[ok[0]]) if ok.size else None)
        hi.append(float(angles_deg[ok[-1]]) if ok.size else None)
        row = np.where(vs.failed[i], "x", np.where(vs.viable[i], "v", "o"))
        rows.append("".join(row.tolist()))
    inside = np.flatnonzero(vs.kernel)
    width = np.array([hi[i] - lo[i] for i in inside])
    return {
        "kernel_s": [float(s[inside[0]]), float(s[inside[-1]])],
        "kernel_h": [float(heights[inside[0]]), float(heights[inside[-1]])],
        "width_deg": {
            "median": float(np.median(width)),
            "p10": float(np.percentile(width, 10)),
            "p90": float(np.percentile(width, 90)),
        },
        "viable_lo_deg": lo,
        "viable_hi_deg": hi,
        "measure": [float(x) for x in vs.measure],
        "plane": rows,
    }


def measure_heim(show_progress: bool | None = None) -> dict:
    p, s, heights, angles = vibly_grid()
    angles_deg = np.linspace(HEIM["angle_deg"][0], HEIM["angle_deg"][1], HEIM["angle_deg"][2])
    sets = {}
    for outside in progress(("edge", "fail"), 2, "Heim and Sproewitz: vibly's SLIP grid", show_progress):
        sets[outside] = viability(
            EXACT, p, apex_height=heights, touchdown_angle=angles, energy=HEIM["energy"], outside=outside
        )
    edge = sets["edge"]
    ok = edge.status[~edge.failed]
    assert ok.size == 0 or np.all(ok == 0), "a completed step is OK"
    from slipmaps.generated.status import Status

    failures = {}
    for code in np.unique(edge.status[edge.failed]):
        failures[Status(int(code)).name] = int(np.sum(edge.status[edge.failed] == code))
    failures = dict(sorted(failures.items(), key=lambda kv: -kv[1]))
    return {
        "source": [
            source(
                "Heim and Sproewitz",
                "Beyond basins of attraction: quantifying robustness of natural dynamics",
                "IEEE Transactions on Robotics 35(4), 939-952",
                2019,
            ),
            source(
                "Heim",
                "",
                "vibly (github.com/sheim/vibly): demos/computeQ_slip.py and its published arrays "
                "tests/integration/data/slip_map.npz",
                None,
            ),
        ],
        "claim": "vibly's SLIP demo (m 80 kg, k 8200 N/m, l0 1 m, g 9.81 m/s^2, flight energy 1877.08 J; "
        "the state s = m g y / E on 180 points in [0.1, 0.995], the angle of attack from the vertical on "
        "-10 ... 70 deg in 161 steps; a step fails when the foot would start underground, the body falls "
        "or the forward speed is no longer positive) has the failure set Q_F, the viable set Q_V and the "
        "measure of robustness S_M of its published arrays",
        "paper": {"setting": dict(HEIM), **VIBLY},
        "setting": {"params": p.as_dict(), "energy": HEIM["energy"], "map": EXACT, "outside": "edge"},
        "ours": {**set_numbers(edge, s), "failures": failures, "rounds": int(edge.rounds)},
        "outside_fail": set_numbers(sets["fail"], s),
        "shape": _shape(edge, s, heights, angles_deg),
        "shape_fail": {
            k: v for k, v in _shape(sets["fail"], s, heights, angles_deg).items() if k not in ("plane",)
        },
    }
