"""ctypes bindings of the C99 deadbeat solver (derive/templates/c/deadbeat.{h,c}.j2).

The C solver is a port of :mod:`slipmaps.runtime.control.compiled`; these mirror its two structs,
convert a numba :class:`~slipmaps.runtime.control.compiled.Settings` into the C one
(:func:`c_settings`), and solve rows with a compiled library's ``slipmaps_deadbeat_solve_rows``
(:func:`solve_rows`), the maps given as C function pointers (``int f(const double *x, const double
*p, double *out)``: the generated C maps, or numba ``cfunc`` addresses).
"""

from __future__ import annotations

import ctypes

import numpy as np
from numba import njit

from ..control import compiled

__all__ = [
    "MAX_OUT",
    "MAX_P",
    "MAX_X",
    "DeadbeatSettings",
    "DeadbeatWork",
    "bind",
    "c_settings",
    "solve_rows",
]

#: The work struct's buffers (the header's SLIPMAPS_MAX_X, _P, _OUT).
MAX_X, MAX_P, MAX_OUT = 16, 32, 192

_I, _D = ctypes.c_int, ctypes.c_double
#: compiled.SETTINGS's fields as the C struct has them: int for an int64, double for a float64.
_SETTINGS = [
    ("n_controls", _I),
    ("in_p", _I * 3),
    ("pos", _I * 3),
    ("col", _I * 3),
    ("lo", _D * 3),
    ("hi", _D * 3),
    ("scale", _D * 3),
    ("targeted", _I * 2),
    ("weight", _D * 2),
    ("tol", _D),
    ("n_out", _I),
    ("n_wrt", _I),
    ("fd_step", _D),
    ("out_height", _I),
    ("out_speed", _I),
    ("kd_in_p", _I),
    ("kd_pos", _I),
    ("kd_lo", _D),
    ("kd_hi", _D),
    ("mass", _D),
    ("g_f", _D),
    ("max_evaluations", _I),
    ("broyden", _I),
    ("scan", _I),
]
if [name for name, _ in _SETTINGS] != list(compiled.SETTINGS):
    raise RuntimeError("runtime/export/deadbeat_c.py: the C settings no longer match compiled.SETTINGS")


class DeadbeatSettings(ctypes.Structure):
    """``slipmaps_deadbeat_settings``."""

    _fields_ = _SETTINGS


_V = {"x": MAX_X, "p": MAX_P, "d": MAX_OUT, "v": MAX_OUT, "e": MAX_OUT, "G": 6, "Gb": 6, "J": 6, "A": 9}
_WORK_ORDER = (
    "x p target d v e u0 z zlo zhi G zb Gb rf J r rt F delta zt free_ rows cols A b zs rs ri rg stall"
).split()
_WORK_SIZES = {"target": 2, "rf": 2, "r": 2, "rt": 2, "F": 2, "rows": 2, "rs": 2, "ri": 2, "rg": 2}


def _work_field(name):
    if name == "stall":
        return name, _D
    kind = _I if name in ("free_", "rows", "cols") else _D
    return name, kind * _V.get(name, _WORK_SIZES.get(name, 3))


class DeadbeatWork(ctypes.Structure):
    """``slipmaps_deadbeat_work`` (fixed-size buffers: one per thread)."""

    _fields_ = [_work_field(name) for name in _WORK_ORDER]


@njit(cache=True)
def _values(s):
    """A numba Settings' fields, in compiled.SETTINGS's order (a proxy's fields are not Python
    attributes)."""
    return (
        s.n_controls, s.in_p, s.pos, s.col, s.lo, s.hi, s.scale, s.targeted, s.weight, s.tol,
        s.n_out, s.n_wrt, s.fd_step, s.out_height, s.out_speed, s.kd_in_p, s.kd_pos, s.kd_lo,
        s.kd_hi, s.mass, s.g_f, s.max_evaluations, s.broyden, s.scan,
    )  # fmt: skip


def c_settings(s: compiled.Settings) -> DeadbeatSettings:
    """The C settings of a numba :class:`~slipmaps.runtime.control.compiled.Settings`."""
    c = DeadbeatSettings()
    for (name, kind), value in zip(_SETTINGS, _values(s), strict=True):
        if hasattr(kind, "_length_"):
            getattr(c, name)[:] = [kind._type_(v).value for v in np.asarray(value).tolist()]
        else:
            setattr(c, name, kind(value).value)
    return c


_P = ctypes.c_void_p
_DP = ctypes.POINTER(ctypes.c_double)


def bind(lib: ctypes.CDLL) -> ctypes.CDLL:
    """Declare the solver's functions of a loaded library (returns it)."""
    f = lib.slipmaps_deadbeat_solve_rows
    f.restype = ctypes.c_int
    f.argtypes = [_P, _P, _DP, _I, _I, _DP, _I, _I, _DP, ctypes.POINTER(DeadbeatSettings),
                  ctypes.POINTER(DeadbeatWork), _DP]  # fmt: skip
    g = lib.slipmaps_deadbeat_solve
    g.restype = ctypes.c_int
    g.argtypes = [_P, _P, _DP, _I, _DP, _I, _DP, ctypes.POINTER(DeadbeatSettings),
                  ctypes.POINTER(DeadbeatWork), _DP]  # fmt: skip
    return lib


def _ptr(a: np.ndarray):
    return a.ctypes.data_as(_DP)


def solve_rows(lib, apex: int, jac: int | None, X, P, T, settings, n_head: int = compiled.N_HEAD):
    """Solve every row with the C solver of ``lib`` (:func:`bind`): the maps' C function pointers
    ``apex``, ``jac`` (addresses; ``jac`` None with ``fd_step`` > 0), inputs ``X`` (n, nx),
    parameter records ``P`` (1 or n rows), targets ``T`` (n, 2), ``settings`` a numba or C
    settings; the rows (n, N_HEAD + n_out) as :meth:`compiled.Solver.run` returns them, and the
    count of rows the solver refused."""
    s = settings if isinstance(settings, DeadbeatSettings) else c_settings(settings)
    X, P, T = (np.ascontiguousarray(a, dtype=np.float64) for a in (X, P, T))
    n = X.shape[0]
    OUT = np.empty((n, n_head + s.n_out))
    w = DeadbeatWork()
    refused = lib.slipmaps_deadbeat_solve_rows(
        apex, jac, _ptr(X), n, X.shape[1], _ptr(P), P.shape[0], P.shape[1], _ptr(T), ctypes.byref(s),
        ctypes.byref(w), _ptr(OUT),
    )  # fmt: skip
    return OUT, refused
