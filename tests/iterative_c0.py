"""Outputs of the map ``iterative`` and its halves at c = 0 as float.hex, for the bitwise check of
tests/test_iterative_damped.py against tests/data/iterative_c0.json (the outputs before the leg
damping entered these maps). ``python tests/iterative_c0.py`` writes the file from the code checked
out: run it only on code whose lossless arithmetic is the reference.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import slipmaps
from slipmaps.runtime.api.params import HUMAN_RUNNER

DATA = Path(__file__).resolve().parent / "data" / "iterative_c0.json"

PARAMS = {"human": HUMAN_RUNNER, "variable": HUMAN_RUNNER.with_(k_d=24_000.0, q_r_lo=0.98)}
TOUCHDOWNS = np.array([(1.0, -1.2, 0.35, -4.6), (0.99, -0.8, 0.2, -3.0), (1.0, -1.5, 0.3, -5.0)])
APEXES = (np.array([1.0, 1.05, 1.1]), np.array([3.0, 5.0, 6.5]), np.array([0.3, 0.4, 0.45]))
#: Options of the whole map and the compression half (every node count, no pass, a tolerance that
#: stops early, the held zeroth iterate); the Jacobians at the first JACOBIAN_OPTIONS of them.
OPTIONS = (
    {},
    {"nodes": "1"},
    {"nodes": "2"},
    {"nodes": "3", "iterations": 3},
    {"nodes": "6"},
    {"iterations": 0},
    {"tol": 1e-6},
    {"tol": 1e-9, "iterations": 20},
    {"zeroth": "held"},
    {"zeroth": "held", "nodes": "2", "iterations": 2},
)
JACOBIAN_OPTIONS = 3


def _hex(values) -> list[str]:
    return [float(x).hex() for x in np.ravel(np.asarray(values, dtype=float))]


def _batch(res) -> dict:
    return {n: _hex(res[n]) for n in res.names} | {"status": [int(s) for s in res.status]}


def outputs(**extra) -> list[dict]:
    """Every case's outputs as float.hex (``extra``: options added to every call, e.g. a liftoff)."""
    cases = []
    for name, p in PARAMS.items():
        for j, opt in enumerate(OPTIONS):
            o = {**opt, **extra}
            case = {
                "map": "iterative",
                "params": name,
                "options": opt,
                "stance": _batch(slipmaps.stance_batch("iterative", p, TOUCHDOWNS, **o)),
                "apex": _batch(slipmaps.apex_return_batch("iterative", p, *APEXES, **o)),
            }
            if j < JACOBIAN_OPTIONS:
                two = [a[:2] for a in APEXES]
                for role, jac in (
                    ("stance_jacobian", slipmaps.stance_jacobian_batch("iterative", p, TOUCHDOWNS[:2], **o)),
                    ("apex_jacobian", slipmaps.apex_return_jacobian_batch("iterative", p, *two, **o)),
                ):
                    keep = [i for i, w in enumerate(jac.inputs) if w != "c"]
                    case[role] = {
                        "inputs": [jac.inputs[i] for i in keep],
                        "matrix": _hex(jac.matrix[..., keep]),
                    }
            cases.append(case)
            half = slipmaps.half_stance_batch("iterative-compression", p, TOUCHDOWNS, **opt)
            cases.append(
                {"map": "iterative-compression", "params": name, "options": opt, "half": _batch(half)}
            )
        bottoms = np.asarray(slipmaps.half_stance_batch("iterative-compression", p, TOUCHDOWNS)["end"])
        for opt in OPTIONS:
            if "zeroth" in opt:
                continue
            half = slipmaps.half_stance_batch("iterative-decompression", p, bottoms, **opt, **extra)
            cases.append(
                {"map": "iterative-decompression", "params": name, "options": opt, "half": _batch(half)}
            )
    return cases


if __name__ == "__main__":
    DATA.write_text(json.dumps(outputs(), separators=(",", ":")) + "\n")
    print(f"wrote {DATA} ({DATA.stat().st_size} bytes)", file=sys.stderr)
