"""ctypes bindings of the C99 swing-policy evaluation (derive/templates/c/swing.{h,c}.j2).

The C functions port :mod:`slipmaps.runtime.control.swing_tables` (the numba evaluation of a
:class:`~slipmaps.runtime.control.swing.SwingPolicy`'s tables). :func:`bind` declares their types
on a compiled library; the functions below call them on numpy tables as the numba ones take them
(rows x knots, float64, NaN padded; ``counts`` converted to C ``int``), and on a policy's tables
(:class:`~slipmaps.runtime.control.swing.PolicyTables`) as its ``controls_at`` and ``touchdown``
do. The tests hold them to the numba evaluation; a robot links the C files directly.
"""

from __future__ import annotations

import ctypes

import numpy as np

from ..control import swing_tables

__all__ = [
    "TABLE",
    "bind",
    "slopes",
    "slopes_rows",
    "evaluate_rows",
    "touchdown_rows",
    "controls_at",
    "touchdown",
    "stacked",
    "step",
]

#: The controls of a policy's tables, in PolicyTables's order (the angle first: slipmaps_swing_step).
TABLE = ("touchdown_angle", "k_c", "k_d")

_I, _D, _P = ctypes.c_int, ctypes.c_double, ctypes.c_void_p
_SIGNATURES = {
    "slipmaps_swing_slopes": (None, [_P, _P, _I, _P]),
    "slipmaps_swing_value": (_D, [_P, _P, _P, _I, _D]),
    "slipmaps_swing_controls_at": (None, [_P, _I, _P, _P, _I, _I, _D, _P]),
    "slipmaps_swing_touchdown": (_I, [_D, _D, _D, _D, _P, _P, _P, _I, _P, _P, _P]),
    "slipmaps_swing_step": (_I, [_D, _D, _D, _D, _P, _I, _P, _P, _I, _I, _P, _P, _P]),
    "slipmaps_swing_slopes_rows": (None, [_P, _P, _P, _I, _I, _P]),
    "slipmaps_swing_evaluate_rows": (None, [_P, _P, _P, _P, _I, _I, _P, _I, _P]),
    "slipmaps_swing_touchdown_rows": (None, [_P, _P, _I, _D, _D, _P, _P, _P, _P, _I, _I, _P, _P, _P, _P]),
}


def bind(lib: ctypes.CDLL) -> ctypes.CDLL:
    """Declare the swing functions' types on ``lib`` (a library compiled with slipmaps_swing.c)."""
    for name, (res, args) in _SIGNATURES.items():
        f = getattr(lib, name)
        f.restype, f.argtypes = res, args
    return lib


def _f64(a) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.float64)


def _tables(T, *others):
    T = _f64(np.atleast_2d(T))
    return (T, *(_f64(np.atleast_2d(x)) for x in others))


def slopes(lib, t, y) -> np.ndarray:
    """The three-point slopes of one table's knots ``t``, ``y`` (``slipmaps_swing_slopes``)."""
    t, y = _f64(t), _f64(y)
    m = np.empty_like(t)
    lib.slipmaps_swing_slopes(t.ctypes.data, y.ctypes.data, t.shape[0], m.ctypes.data)
    return m


def slopes_rows(lib, T, Y, counts) -> np.ndarray:
    """``swing_tables.slopes_rows`` in C: the slopes of every row with knots (NaN elsewhere)."""
    T, Y = _tables(T, Y)
    c = np.ascontiguousarray(counts, dtype=np.intc)
    M = swing_tables.empty_slopes(T)
    lib.slipmaps_swing_slopes_rows(T.ctypes.data, Y.ctypes.data, c.ctypes.data, T.shape[0], T.shape[1],
                                   M.ctypes.data)  # fmt: skip
    return M


def evaluate_rows(lib, T, Y, M, counts, x) -> np.ndarray:
    """``swing_tables.evaluate_rows`` in C: the interpolant of row min(i, rows - 1) at ``x[i]``."""
    T, Y, M = _tables(T, Y, M)
    c = np.ascontiguousarray(counts, dtype=np.intc)
    x = _f64(np.atleast_1d(x))
    out = np.empty(x.shape[0])
    lib.slipmaps_swing_evaluate_rows(T.ctypes.data, Y.ctypes.data, M.ctypes.data, c.ctypes.data, T.shape[0],
                                     T.shape[1], x.ctypes.data, x.shape[0], out.ctypes.data)  # fmt: skip
    return out


def touchdown_rows(lib, h, ground, g, q, T, A, MA, counts) -> dict[str, np.ndarray]:
    """``swing_tables.touchdown_rows`` in C: per query ``t``, ``angle``, ``where``, ``knot``
    (int64 like the numba outputs)."""
    T, A, MA = _tables(T, A, MA)
    c = np.ascontiguousarray(counts, dtype=np.intc)
    h, ground = (_f64(np.atleast_1d(v)) for v in np.broadcast_arrays(h, ground))
    n = h.shape[0]
    t, angle = np.empty(n), np.empty(n)
    where, knot = np.empty(n, dtype=np.intc), np.empty(n, dtype=np.intc)
    lib.slipmaps_swing_touchdown_rows(
        h.ctypes.data, ground.ctypes.data, n, float(g), float(q), T.ctypes.data, A.ctypes.data,
        MA.ctypes.data, c.ctypes.data, T.shape[0], T.shape[1], t.ctypes.data, angle.ctypes.data,
        where.ctypes.data, knot.ctypes.data,
    )  # fmt: skip
    return {"t": t, "angle": angle, "where": where.astype(np.int64), "knot": knot.astype(np.int64)}


def controls_at(lib, tables, t) -> dict[str, np.ndarray]:
    """``PolicyTables.controls_at`` in C: the controls at times ``t`` (one per row, or any number
    for tables of one row)."""
    return {
        name: evaluate_rows(lib, tables.T, tables.values[name], tables.slopes[name], tables.counts, t)
        for name in TABLE
    }


def touchdown(lib, tables, apex_height, ground) -> dict[str, np.ndarray]:
    """``PolicyTables.touchdown`` in C (without the plan status): ``t``, the controls at that
    instant, ``where`` and ``knot``."""
    name = "touchdown_angle"
    td = touchdown_rows(lib, apex_height, ground, tables.g_f, tables.q_r_td, tables.T, tables.values[name],
                        tables.slopes[name], tables.counts)  # fmt: skip
    out = {"t": td["t"], "touchdown_angle": td["angle"], "where": td["where"], "knot": td["knot"]}
    at = controls_at(lib, tables, np.where(np.isfinite(td["t"]), td["t"], 0.0))
    out["k_c"], out["k_d"] = at["k_c"], at["k_d"]
    return out


def stacked(tables, row: int = 0, controls=TABLE) -> tuple[np.ndarray, np.ndarray]:
    """One policy row's values and slopes stacked as ``slipmaps_swing_step`` and
    ``slipmaps_swing_controls_at`` take them: (len(controls), width), the angle first."""
    Y = np.stack([tables.values[c][row] for c in controls])
    M = np.stack([tables.slopes[c][row] for c in controls])
    return _f64(Y), _f64(M)


def step(lib, tables, apex_height, ground, row: int = 0) -> dict[str, np.ndarray]:
    """``slipmaps_swing_step`` of policy row ``row`` for each (apex height, ground) pair, one C call
    each (a robot's per-step call): ``t``, the controls, ``where``, ``knot``."""
    Y, M = stacked(tables, row)
    t = _f64(tables.T[row])
    h, ground = (np.atleast_1d(np.asarray(v, dtype=float)) for v in np.broadcast_arrays(apex_height, ground))
    n, nc = h.shape[0], Y.shape[0]
    out = {"t": np.empty(n), **{c: np.empty(n) for c in TABLE}}
    where, knot = np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
    t_out, ctl, k = ctypes.c_double(), (ctypes.c_double * nc)(), ctypes.c_int()
    f = lib.slipmaps_swing_step
    count, width = int(tables.counts[row]), Y.shape[1]
    table = (t.ctypes.data, count, Y.ctypes.data, M.ctypes.data, nc, width)
    outs = (ctypes.byref(t_out), ctl, ctypes.byref(k))
    for i in range(n):
        where[i] = f(float(h[i]), float(ground[i]), tables.g_f, tables.q_r_td, *table, *outs)
        out["t"][i] = t_out.value
        for j, c in enumerate(TABLE):
            out[c][i] = ctl[j]
        knot[i] = k.value
    out["where"], out["knot"] = where, knot
    return out
