"""The deadbeat solve compiled with numba: a bounded, safeguarded Gauss-Newton method on a map's kernels.

One generic solver (:func:`solve_row`) for every map: it takes the map's apex-return kernel and its
apex-return Jacobian kernel as arguments, wrapped per map by :func:`kernels_for` into two small
functions of a float64 argument vector ``a`` (the kernel's arguments by position: the apex, the
touchdown angle, the ground, the parameters with the stiffness, the map's options) that write the
outputs into a work vector. Nothing here knows a map: the argument positions, the output columns and
the Jacobian's columns come from the generated index (:class:`~slipmaps.runtime.api.calls.Call`).

The solver takes the wrappers as first-class functions of one signature (:data:`WRAPPER`), so it is
compiled once for every map and cached on disk like the kernels; the wrappers and the two entry
points bound to them (scalar, parallel batch) are built from the index and compiled once per map
and process (a few seconds: they link the map's kernels). A solve then costs one call from Python
(about 0.3 us) and the map's kernel calls.

The method (the controls u, at most 3; the targets the next apex height and speed, 1 or 2):

* scaled unknowns z_j = (u_j - u0_j) / s_j (u0: the starting controls, the stiffness nominal), the
  residual r = w (F(u) - T) with w = 1/l0 for the height and 1/sqrt(g_f l0) for the speed (0 for a
  target left out);
* a step: the damped minimum-norm Gauss-Newton step -J^T (J J^T + mu)^-1 r when the controls are at
  least as many as the targets, plus the pull -(I - J^T (J J^T + mu)^-1 J) z toward the starting
  controls in the null space (more controls than targets: the least change, in the scaled norm, among
  the controls that reach the target); -(J^T J + mu)^-1 J^T r with fewer controls than targets;
* box bounds by projection, with an active set: a control at a bound whose descent direction leaves
  the box is held there for the step;
* a backtracking line search on |r|^2 (a trial where the map fails counts as no decrease); the
  Jacobian is the map's generated one at the start and, with ``broyden``, rank-one secant updates
  (Broyden's good update) after each accepted step (a fresh one when a line search fails), else a
  fresh one after every step; mu grows when a line search fails with a fresh Jacobian;
* stop when |r| <= tol (and the pull has stopped moving), or when no step decreases |r| (the
  closest reachable point of that neighbourhood: UNREACHABLE), or after ``max_iter`` Jacobians;
* one control (the touchdown angle alone, or k_d at the bottom): if that does not reach the target,
  a scan of the control's whole range (``scan`` points), then the sign change nearest the start
  bracketed and solved by the Illinois method (one target), or Gauss-Newton again from the scan's
  best point (two targets, least squares); the same scan restarts a solve whose start fails.

Plan statuses (:data:`REACHED`, :data:`UNREACHABLE`, :data:`MAP_FAILED`) are written in the row's
head (:data:`HEAD`) beside the map's own status of the final point.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from slipmaps.generated.flight import liftoff_to_apex
from slipmaps.generated.status import Status

__all__ = [
    "HEAD",
    "MAP_FAILED",
    "REACHED",
    "UNREACHABLE",
    "BOTTOM_OUTPUTS",
    "Kernels",
    "ascent",
    "bottom_kernels_for",
    "in_threads",
    "kernels_for",
]

#: Plan statuses as written by the solver (the Python layer's :class:`~.deadbeat.PlanStatus`).
REACHED, UNREACHABLE, MAP_FAILED = 0, 1, 2

#: The head of a solver row: its fields by name (then the map's apex-return outputs at the final point).
HEAD = (
    "plan_status",  # REACHED / UNREACHABLE / MAP_FAILED
    "map_status",  # the map's Status at the final point (or at the first failure)
    "jacobians",  # Jacobian evaluations (the generated kernel)
    "evaluations",  # apex-return evaluations (line search, scan, bracketing)
    "iterations",  # accepted steps
    "u0",
    "u1",
    "u2",  # the controls at the final point, in the order given
    "residual",  # |r| (scaled) at the final point
    "authority",  # dE'/dk_d [J per N/m] at the final controls (the secant between the k_d bounds)
    "energy_low",  # the next apex's flight energy m (g_f h' + v'^2/2) [J] with k_d at its lower bound
    "energy_high",  # ... at its upper bound (the other controls as found); NaN where the map fails there
)
N_HEAD = len(HEAD)
_PS, _MS, _NJ, _NE, _NI, _U0, _RES, _AUTH, _ELO, _EHI = 0, 1, 2, 3, 4, 5, 8, 9, 10, 11

_OK = int(Status.OK)
_NAN = math.nan
#: Backtracking: at most this many halvings of a step.
_HALVINGS = 12
#: ... of a step on a secant (Broyden) Jacobian, before a fresh one is asked for.
_SECANT_HALVINGS = 3
#: Sufficient decrease of |r|^2, as a fraction of the decrease the linearised residual promises
#: (Armijo's constant).
_ARMIJO = 1e-4
#: The pull toward the start has stopped when it moves the scaled controls by less than this.
_PULL_TOL = 1e-10
#: Rounds of Levenberg damping (mu = 1e-3, then 1e-1 times |J|^2) before a line search gives up.
_DAMPING_ROUNDS = 2
#: A failed line search where the linearised residual promises less than this relative decrease
#: ends at a least-squares minimum (the promise is below the map's and the Jacobian's noise).
_FLAT = 1e-8
#: Failed line searches a Gauss-Newton run may have (each followed by a fresh Jacobian or damping).
_MAX_FAIL = 3
#: Golden-section steps of the closest point of one control (0.618^30 = 5e-7 of two scan steps).
_GOLDEN_ITER = 30
#: Illinois iterations on a bracket at most.
_BRACKET_ITER = 80


#: The wrapped kernels' signature: ``f(a, d)``, both C-contiguous float64 vectors. Every map's wrappers
#: have it, so the solver takes them as first-class functions of this one type and is compiled (and
#: cached on disk) once for every map.
WRAPPER = types.void(types.float64[::1], types.float64[::1])
_FN = types.FunctionType(WRAPPER)
_VEC = types.float64[::1]
_SOLVE = types.void(_FN, _FN, _VEC, types.int64[::1], _VEC, _VEC, _VEC)


class Kernels:
    """A map's two wrapped kernels (compiled per map): ``apex(a, d)`` writes the status into
    ``d[0]`` and the apex-return outputs into ``d[1:1 + n_out]``; ``jac(a, d)`` the same, then
    d apex_height / d wrt_j into ``d[1 + n_out + j]`` and d apex_speed / d wrt_j into
    ``d[1 + n_out + n_wrt + j]``. ``scalar`` and ``batch`` are the solver bound to them."""

    def __init__(self, apex, jac, scalar, batch, n_args, n_out, n_wrt, one=None):
        self.apex, self.jac, self.scalar, self.batch = apex, jac, scalar, batch
        self.n_args, self.n_out, self.n_wrt = n_args, n_out, n_wrt
        self.one = one

    @property
    def width(self) -> int:
        """The length of a solver row: the head, then the map's outputs."""
        return N_HEAD + self.n_out


def _wrapper_source(name: str, n_args: int, n_out: int, status: int, derivs: list[int]) -> str:
    """Source of ``name(a, d)`` calling the kernel ``F`` on a[0..n_args-1]: d[0] the status (the
    kernel's return value ``status``), d[1+j] output j, then the listed Jacobian entries (their
    positions in the kernel's return tuple)."""
    args = ", ".join(f"a[{i}]" for i in range(n_args))
    lines = [f"def {name}(a, d):", f"    r = F({args})", f"    d[0] = r[{status}]"]
    lines += [f"    d[{1 + j}] = r[{j}]" for j in range(n_out)]
    lines += [f"    d[{1 + n_out + i}] = r[{pos}]" for i, pos in enumerate(derivs)]
    return "\n".join(lines) + "\n"


_CACHE: dict = {}


def kernels_for(call) -> Kernels:
    """The wrapped kernels and the bound solver of ``call``'s map (compiled once per map; the
    argument order is the index's, the same for every parameter set and option choice)."""
    spec_a, spec_j = call.spec("apex_return"), call.spec("apex_return_jacobian")
    key = (spec_a.module, spec_a.name, spec_j.module, spec_j.name)
    hit = _CACHE.get(key)
    if hit is not None:
        return hit
    if spec_a.args != spec_j.args:  # the index gives both the same arguments; say so if not
        raise RuntimeError(f"map {call.info.name!r}: apex_return and its Jacobian take different arguments")
    n_args, n_out, n_wrt = len(spec_a.args), len(spec_a.outputs), len(spec_j.wrt)
    i_h, i_v = spec_j.outputs.index("apex_height"), spec_j.outputs.index("apex_speed")
    derivs = [n_out + i_h * n_wrt + j for j in range(n_wrt)] + [n_out + i_v * n_wrt + j for j in range(n_wrt)]
    ns_a = {"F": spec_a.functions()[0]}
    ns_j = {"F": spec_j.functions()[0]}
    exec(_wrapper_source("apex", n_args, n_out, n_out, []), ns_a)  # the source is built here, from the index
    exec(_wrapper_source("jac", n_args, n_out, n_out * (1 + n_wrt), derivs), ns_j)
    apex = njit(WRAPPER, error_model="numpy")(ns_a["apex"])
    jac = njit(WRAPPER, error_model="numpy")(ns_j["jac"])
    scalar, batch = _bind(apex, jac)
    kernels = Kernels(apex, jac, scalar, batch, n_args, n_out, n_wrt, one=_bind_one(apex, jac))
    _CACHE[key] = kernels
    return kernels


@njit(error_model="numpy")
def ascent(q_r, q_rd, q_th, q_thd, g_f):
    """The flight from a liftoff state to the next apex (the generated ``liftoff_to_apex``) in the
    direction the body moves at liftoff: a stance that reverses the direction (a turn from a hop
    in place, or a slight overshoot of a stop) flies on, as the body does."""
    b_xd = -math.sin(q_th) * q_rd - q_r * math.cos(q_th) * q_thd
    direction = 0.0 if b_xd == 0.0 else math.copysign(1.0, b_xd)
    return liftoff_to_apex(q_r, q_rd, q_th, q_thd, g_f, direction)


#: The outputs of the bottom-stage model (a decompression half, then the flight to the apex).
BOTTOM_OUTPUTS = (
    "apex_height",
    "apex_speed",
    "t_half",
    "t_ascent",
    "liftoff_q_r",
    "liftoff_q_rd",
    "liftoff_q_th",
    "liftoff_q_thd",
)
#: Relative step of the central difference in k_d (the half maps have no Jacobian kernel).
FD_STEP = 1e-5


def _bottom_source(n_args: int, status: int, t_half: int, end: tuple[int, ...], i_kd: int) -> str:
    """Source of the bottom model's ``apex(a, d)`` (the decompression half ``H`` on a[0..n_args-1],
    then :func:`ascent` with g_f = a[n_args]) and ``jac(a, d)`` (the same and d/d k_d by a central
    difference)."""
    args = ", ".join(f"a[{i}]" for i in range(n_args))
    lo = ", ".join(f"r[{i}]" for i in end)
    return f"""
def apex(a, d):
    r = H({args})
    if r[{status}] != 0:
        d[0] = r[{status}]
        for j in range(8):
            d[1 + j] = NAN
        return
    x = ascent({lo}, a[{n_args}])
    d[0] = x[5]
    d[1] = x[0]
    d[2] = x[1]
    d[3] = r[{t_half}]
    d[4] = x[2]
    d[5] = r[{end[0]}]
    d[6] = r[{end[1]}]
    d[7] = r[{end[2]}]
    d[8] = r[{end[3]}]


def jac(a, d):
    apex(a, d)
    if d[0] != 0:
        return
    k = a[{i_kd}]
    h = FD_STEP * k
    e = np.empty(9)
    a[{i_kd}] = k + h
    apex(a, e)
    hp, vp, sp = e[1], e[2], e[0]
    a[{i_kd}] = k - h
    apex(a, e)
    a[{i_kd}] = k
    if sp != 0 or e[0] != 0:
        d[0] = sp if sp != 0 else e[0]
        return
    d[9] = (hp - e[1]) / (2.0 * h)
    d[10] = (vp - e[2]) / (2.0 * h)
"""


def bottom_kernels_for(call) -> Kernels:
    """The bottom-stage model of a decompression half map (``call``: the half, :mod:`.bottom`):
    its wrapped kernels and the bound solver, compiled once per half map."""
    spec = call.spec("half")
    key = ("bottom", spec.module, spec.name)
    hit = _CACHE.get(key)
    if hit is not None:
        return hit
    n_args = len(spec.args)
    end = tuple(spec.outputs.index(f"end_{q}") for q in ("q_r", "q_rd", "q_th", "q_thd"))
    source = _bottom_source(
        n_args, len(spec.outputs), spec.outputs.index("t_half"), end, spec.args.index("k_d")
    )
    ns = {"H": spec.functions()[0], "ascent": ascent, "NAN": _NAN, "FD_STEP": FD_STEP, "np": np}
    exec(source, ns)  # the source is built here, from the index
    apex = njit(WRAPPER, error_model="numpy")(ns["apex"])
    ns["apex"] = apex
    jac = njit(WRAPPER, error_model="numpy")(ns["jac"])
    scalar, batch = _bind(apex, jac)
    kernels = Kernels(apex, jac, scalar, batch, n_args + 1, len(BOTTOM_OUTPUTS), 1)
    _CACHE[key] = kernels
    return kernels


def _bind(apex, jac):
    """The solver bound to one map's wrapped kernels: ``scalar(a, ints, floats, out)`` and the
    batch ``batch(A, ints, floats, OUT)`` over the rows of A (one argument vector per row), on
    numba's thread count in chunks (:func:`in_threads`). One compiled entry (a loop over rows,
    releasing the GIL) serves both: numba's parallel loops would compile the map's kernels again."""

    @njit(error_model="numpy", nogil=True)
    def rows(A, ints, floats, OUT):
        W = np.empty(N_WORK + 1 + ints[_I_NOUT] + 2 * ints[_I_NWRT])
        for i in range(A.shape[0]):
            a = A[i].copy()
            solve_row(apex, jac, a, ints, floats, W, OUT[i])

    def scalar(a, ints, floats, out):
        rows(a.reshape(1, -1), ints, floats, out.reshape(1, -1))

    def batch(A, ints, floats, OUT):
        in_threads(rows, A, OUT, ints, floats)

    return scalar, batch


_POOL = None


def _bind_one(apex, jac):
    """The scalar solve's fast entry: ``one(T, h, v, ground, angle, H, V, ints, floats, out)`` copies
    the row template T and puts the apex, the ground, the starting angle and the targets at their
    positions (``ints``) in compiled code (a deadbeat step's Python side is then a few checks)."""

    @njit(error_model="numpy", nogil=True)
    def one(T, h, v, gr, th, H, V, ints, floats, out):
        a = T.copy()
        a[ints[_I_POS]] = h
        a[ints[_I_POS + 1]] = v
        a[ints[_I_POS + 2]] = gr
        a[ints[_I_POS + 3]] = th
        a[ints[_I_NARGS]] = H
        a[ints[_I_NARGS] + 1] = V
        W = np.empty(N_WORK + 1 + ints[_I_NOUT] + 2 * ints[_I_NWRT])
        solve_row(apex, jac, a, ints, floats, W, out)

    return one


def in_threads(rows, A, OUT, *shared) -> None:
    """``rows(A[chunk], *shared, OUT[chunk])`` over contiguous chunks of the rows, one per numba
    thread (``numba.get_num_threads()``), in Python threads (``rows`` releases the GIL)."""
    import numba

    n = A.shape[0]
    k = max(1, min(numba.get_num_threads(), n // 8 or 1))
    if k == 1:
        rows(A, *shared, OUT)
        return
    from concurrent.futures import ThreadPoolExecutor

    bounds = np.linspace(0, n, k + 1).astype(int)
    with ThreadPoolExecutor(max_workers=k) as pool:
        jobs = [
            pool.submit(rows, A[lo:hi], *shared, OUT[lo:hi])
            for lo, hi in zip(bounds[:-1], bounds[1:], strict=True)
        ]
        for job in jobs:
            job.result()


# ----------------------------------------------------------------------------------------------
# The solver's integer and float settings, by position (built by :mod:`.deadbeat`)
# ----------------------------------------------------------------------------------------------
#: ints: n_out, n_wrt, output row of apex_height, of apex_speed, number of controls, their argument
#: positions (3), their Jacobian columns (3), the k_d column (-1: none), max evaluations, broyden
#: (0/1), scan points, the targeted components (2: 1 or 0), the kernel's argument count (the target
#: height and speed follow the arguments in a row), the k_d argument's position (-1: none), the
#: positions of the apex height, the apex speed, the ground and the touchdown angle.
_I_NOUT, _I_NWRT, _I_OH, _I_OV, _I_NC = 0, 1, 2, 3, 4
_I_ARG, _I_COL = 5, 8
_I_KD, _I_MAXJ, _I_BROYDEN, _I_SCAN, _I_TGT, _I_NARGS, _I_KDARG, _I_POS = 11, 12, 13, 14, 15, 17, 18, 19
N_INTS = 23
#: floats: lower bounds (3), upper bounds (3), scales (3), residual weights (2), tol, the mass and
#: g_f, the bounds of k_d (for the energy budget).
_F_LO, _F_HI, _F_S, _F_W, _F_TOL, _F_M, _F_G = 0, 3, 6, 9, 11, 12, 13
_F_KDLO, _F_KDHI = 14, 15
N_FLOATS = 16

INT_FIELDS = {"n_out": 0, "n_wrt": 1, "out_height": 2, "out_speed": 3, "n_controls": 4, "arg": 5, "col": 8}
INT_FIELDS |= {"kd_col": 11, "max_evaluations": 12, "broyden": 13, "scan": 14, "targeted": 15, "n_args": 17}
INT_FIELDS |= {"kd_arg": 18, "positions": 19}  # positions: the apex height, speed, ground, angle
FLOAT_FIELDS = {
    "lo": 0,
    "hi": 3,
    "scale": 6,
    "weight": 9,
    "tol": 11,
    "m": 12,
    "g_f": 13,
    "kd_lo": 14,
    "kd_hi": 15,
}


# The work buffer W of a solve (one allocation): fixed regions, then the kernels' outputs d.
_W_U0, _W_Z, _W_ZLO, _W_ZHI, _W_G, _W_ZB, _W_GB, _W_RF = 0, 3, 6, 9, 12, 18, 21, 27
_W_J, _W_R, _W_RT, _W_F, _W_DELTA, _W_ZT, _W_FREE = 29, 35, 37, 39, 41, 44, 47
_W_A, _W_B, _W_ROWS, _W_COLS = 50, 59, 62, 64
_W_ZS, _W_RS, _W_RI, _W_RG = 67, 70, 72, 74
_W_STALL = 76  # 1 when the last Gauss-Newton run ended on a failed line search or its budget
N_WORK = 77


@njit(error_model="numpy")
def _residual(d, a, ints, floats, r):
    """r (2) from the outputs in d: w (F - T) for the targeted components, 0 for the others (the
    targets T follow the kernel's arguments in a); returns |r|^2."""
    h = d[1 + ints[_I_OH]]
    v = d[1 + ints[_I_OV]]
    t = ints[_I_NARGS]
    r[0] = floats[_F_W] * (h - a[t]) if ints[_I_TGT] else 0.0
    r[1] = floats[_F_W + 1] * (v - a[t + 1]) if ints[_I_TGT + 1] else 0.0
    return r[0] * r[0] + r[1] * r[1]


@njit(error_model="numpy")
def _set_controls(a, z, u0, ints, floats):
    for j in range(ints[_I_NC]):
        a[ints[_I_ARG + j]] = u0[j] + floats[_F_S + j] * z[j]


@njit(error_model="numpy")
def _jacobian_raw(d, ints, floats, G):
    """G (2 x 3, row-major): d(apex_height, apex_speed) / d z_j from a Jacobian evaluation in d."""
    n_out, n_wrt = ints[_I_NOUT], ints[_I_NWRT]
    for j in range(ints[_I_NC]):
        col = ints[_I_COL + j]
        s = floats[_F_S + j]
        G[j] = d[1 + n_out + col] * s
        G[3 + j] = d[1 + n_out + n_wrt + col] * s


@njit(error_model="numpy")
def _weighted(G, ints, floats, J):
    """J = d r / d z: the rows of G weighted, zero for a component that is not a target."""
    for j in range(ints[_I_NC]):
        J[j] = floats[_F_W] * G[j] if ints[_I_TGT] else 0.0
        J[3 + j] = floats[_F_W + 1] * G[3 + j] if ints[_I_TGT + 1] else 0.0


@njit(error_model="numpy")
def _solve_small(A, b, n):
    """Solve A x = b (A n x n row-major in a 3 x 3 block, n <= 3) by Gaussian elimination with
    partial pivoting (A, b overwritten; x in b); returns False when A is singular."""
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(A[3 * i + k]) > abs(A[3 * p + k]):
                p = i
        if A[3 * p + k] == 0.0 or not math.isfinite(A[3 * p + k]):
            return False
        if p != k:
            for j in range(n):
                A[3 * k + j], A[3 * p + j] = A[3 * p + j], A[3 * k + j]
            b[k], b[p] = b[p], b[k]
        for i in range(k + 1, n):
            f = A[3 * i + k] / A[3 * k + k]
            for j in range(k, n):
                A[3 * i + j] -= f * A[3 * k + j]
            b[i] -= f * b[k]
    for k in range(n - 1, -1, -1):
        s = b[k]
        for j in range(k + 1, n):
            s -= A[3 * k + j] * b[j]
        b[k] = s / A[3 * k + k]
    return True


@njit(error_model="numpy")
def _step(A, b, rows, cols, J, r, z, free, nc, mu, delta):
    """The damped Gauss-Newton step over the free controls (module docstring) into delta, with the
    work vectors A (9), b (3), rows (2), cols (3); False when the linear system is singular. Rows of
    J for untargeted components are zero and dropped."""
    m = 0
    for i in range(2):
        nz = r[i] != 0.0
        for j in range(nc):
            if free[j] != 0.0 and J[3 * i + j] != 0.0:
                nz = True
        if nz:
            rows[m] = i
            m += 1
    n = 0
    for j in range(nc):
        delta[j] = 0.0
        if free[j] != 0.0:
            cols[n] = j
            n += 1
    if n == 0 or m == 0:
        return False
    for i in range(9):
        A[i] = 0.0
    if n >= m:
        # b = (J J^T + mu I)^-1 (r - J z), delta = -J^T b - z: the minimum-norm (least change from
        # the start) step of the linearised equations, damped.
        for p in range(m):
            rp = 3 * int(rows[p])
            for q in range(m):
                rq = 3 * int(rows[q])
                s = 0.0
                for c in range(n):
                    jc = int(cols[c])
                    s += J[rp + jc] * J[rq + jc]
                A[3 * p + q] = s
            A[3 * p + p] += mu
            jz = 0.0
            for c in range(n):
                jc = int(cols[c])
                jz += J[rp + jc] * z[jc]
            b[p] = r[int(rows[p])] - jz
        if not _solve_small(A, b, m):
            return False
        for c in range(n):
            jc = int(cols[c])
            s = 0.0
            for p in range(m):
                s += J[3 * int(rows[p]) + jc] * b[p]
            delta[jc] = -s - z[jc]
    else:
        for p in range(n):
            jp = int(cols[p])
            for q in range(n):
                jq = int(cols[q])
                s = 0.0
                for i in range(m):
                    ri = 3 * int(rows[i])
                    s += J[ri + jp] * J[ri + jq]
                A[3 * p + q] = s
            A[3 * p + p] += mu
            s = 0.0
            for i in range(m):
                s += J[3 * int(rows[i]) + jp] * r[int(rows[i])]
            b[p] = -s
        if not _solve_small(A, b, n):
            return False
        for c in range(n):
            delta[int(cols[c])] = b[c]
    for j in range(nc):
        if not math.isfinite(delta[j]):
            return False
    return True


@njit(error_model="numpy")
def _evaluate(apex, a, z, u0, ints, floats, d, r, out):
    """The map at controls z: |r|^2, or inf when the map fails there (its status in d[0])."""
    _set_controls(a, z, u0, ints, floats)
    apex(a, d)
    out[_NE] += 1.0
    if int(d[0]) != _OK:
        return math.inf
    return _residual(d, a, ints, floats, r)


@njit(error_model="numpy")
def _fresh(jac, a, z, u0, ints, floats, d, out, G):
    """A Jacobian of the map at z into G; False when the map (or its derivative) fails there."""
    _set_controls(a, z, u0, ints, floats)
    jac(a, d)
    out[_NJ] += 1.0
    if int(d[0]) != _OK:
        return False
    _jacobian_raw(d, ints, floats, G)
    return True


@njit(error_model="numpy")
def _gauss_newton(apex, jac, a, z, u0, zlo, zhi, ints, floats, W, d, out, G, max_fail):
    """Bounded, line-searched Gauss-Newton from z (updated in place; G holds the last Jacobian,
    dF/dz); at most ``max_fail`` failed line searches. Returns |r|^2 at the end (inf when the map
    fails at the start: d[0] holds its status)."""
    nc = ints[_I_NC]
    m = ints[_I_TGT] + ints[_I_TGT + 1]
    tol2 = floats[_F_TOL] ** 2
    broyden = ints[_I_BROYDEN] != 0
    J = W[_W_J : _W_J + 6]
    r = W[_W_R : _W_R + 2]
    rt = W[_W_RT : _W_RT + 2]
    F = W[_W_F : _W_F + 2]
    delta = W[_W_DELTA : _W_DELTA + 3]
    zt = W[_W_ZT : _W_ZT + 3]
    free = W[_W_FREE : _W_FREE + 3]
    A = W[_W_A : _W_A + 9]
    b = W[_W_B : _W_B + 3]
    rows = W[_W_ROWS : _W_ROWS + 2]
    cols = W[_W_COLS : _W_COLS + 3]
    for i in range(6):
        J[i] = 0.0
    W[_W_STALL] = 1.0
    if not _fresh(jac, a, z, u0, ints, floats, d, out, G):
        return math.inf
    phi = _residual(d, a, ints, floats, r)
    F[0], F[1] = d[1 + ints[_I_OH]], d[1 + ints[_I_OV]]
    fresh = True
    damping = 0  # rounds of growing mu since the last accepted step
    fails = 0
    while True:
        _weighted(G, ints, floats, J)
        # free controls: not held at a bound by the descent direction -J^T r
        scale = 0.0
        for j in range(nc):
            gj = J[j] * r[0] + J[3 + j] * r[1]
            held = (z[j] <= zlo[j] and gj > 0.0) or (z[j] >= zhi[j] and gj < 0.0)
            free[j] = 0.0 if held else 1.0
            scale += J[j] ** 2 + J[3 + j] ** 2
        mu = 0.0 if damping == 0 else scale * 1e-3 * 100.0 ** (damping - 1)
        if not _step(A, b, rows, cols, J, r, z, free, nc, mu, delta):
            if damping < _DAMPING_ROUNDS:
                damping += 1
                continue
            break
        # converged: the residual within tol and (more controls than targets) the pull at rest
        size = 0.0
        for j in range(nc):
            size = max(size, abs(delta[j]))
        if phi <= tol2 and (size <= _PULL_TOL or nc <= m):
            W[_W_STALL] = 0.0
            break
        if phi <= tol2 and not fresh:  # the pull toward the start needs the null space exactly
            if not _fresh(jac, a, z, u0, ints, floats, d, out, G):
                break
            fresh = True
            continue
        # stationary: the linearised residual cannot decrease (a least-squares minimum)
        pred = 0.0
        for i in range(2):
            ri = r[i]
            for j in range(nc):
                ri += J[3 * i + j] * delta[j]
            pred += ri * ri
        if phi > tol2 and (phi - pred <= 1e-12 * phi or size <= 1e-14):
            if not fresh:
                if not _fresh(jac, a, z, u0, ints, floats, d, out, G):
                    break
                fresh = True
                continue
            W[_W_STALL] = 0.0
            break
        # Armijo's condition on the decrease the linearised residual promises (a strict decrease)
        decrease = max(phi - pred, 0.0)
        alpha = 1.0
        accepted = False
        phi_t = math.inf
        for _ in range(_HALVINGS if fresh else _SECANT_HALVINGS):
            for j in range(nc):
                zt[j] = min(max(z[j] + alpha * delta[j], zlo[j]), zhi[j])
            phi_t = _evaluate(apex, a, zt, u0, ints, floats, d, rt, out)
            if (phi_t < phi and phi_t <= phi - _ARMIJO * alpha * decrease) or (phi <= tol2 and phi_t <= tol2):
                accepted = True
                break
            alpha *= 0.5
        if not accepted:
            if fresh and phi - pred <= _FLAT * phi:  # no decrease left to find: a minimum
                W[_W_STALL] = 0.0
                break
            fails += 1
            if fails > max_fail:
                break
            if not fresh:  # a secant Jacobian may be off: a fresh one before giving up
                if not _fresh(jac, a, z, u0, ints, floats, d, out, G):
                    break
                fresh = True
                continue
            if damping < _DAMPING_ROUNDS:  # damp toward the gradient direction
                damping += 1
                continue
            break
        out[_NI] += 1.0
        damping = 0
        ht, vt = d[1 + ints[_I_OH]], d[1 + ints[_I_OV]]
        if broyden:
            # G += ((F_t - F) - G s) s^T / (s^T s)
            ss = 0.0
            for j in range(nc):
                ss += (zt[j] - z[j]) ** 2
            if ss > 0.0:
                for i in range(2):
                    y = (ht - F[0]) if i == 0 else (vt - F[1])
                    for j in range(nc):
                        y -= G[3 * i + j] * (zt[j] - z[j])
                    for j in range(nc):
                        G[3 * i + j] += y * (zt[j] - z[j]) / ss
            fresh = False
        for j in range(nc):
            z[j] = zt[j]
        phi = phi_t
        r[0], r[1] = rt[0], rt[1]
        F[0], F[1] = ht, vt
        if out[_NJ] + out[_NE] >= ints[_I_MAXJ]:
            break
        if not broyden:
            if not _fresh(jac, a, z, u0, ints, floats, d, out, G):
                break  # the values just succeeded: a derivative that does not exist
            fresh = True
    return phi


@njit(error_model="numpy")
def _illinois(apex, a, z, u0, ints, floats, W, d, out, za, zb, fa, fb):
    """The one-control, one-target root in the bracket [za, zb] (f(za) f(zb) < 0) by the Illinois
    method; z[0] set to it; returns |r|^2 there."""
    r = W[_W_RI : _W_RI + 2]
    k = 0 if ints[_I_TGT] else 1
    tol = floats[_F_TOL]
    side = 0
    phi = math.inf
    for _ in range(_BRACKET_ITER):
        zc = (za * fb - zb * fa) / (fb - fa)
        if not (min(za, zb) < zc < max(za, zb)):
            zc = 0.5 * (za + zb)
        z[0] = zc
        phi = _evaluate(apex, a, z, u0, ints, floats, d, r, out)
        if phi == math.inf:  # the map fails inside the bracket: keep the side that ran
            zb = zc
            continue
        fc = r[k]
        if phi <= tol * tol or abs(zb - za) <= 1e-15 * max(1.0, abs(zc)):
            return phi
        if (fc < 0.0) == (fa < 0.0):
            za, fa = zc, fc
            if side == -1:
                fb *= 0.5
            side = -1
        else:
            zb, fb = zc, fc
            if side == 1:
                fa *= 0.5
            side = 1
    return phi


@njit(error_model="numpy")
def _golden(apex, a, z, u0, ints, floats, W, d, out, lo, hi):
    """The minimum of |r|^2 over the first control in [lo, hi] (golden section, a failing map
    counting as inf); z[0] set to it; returns |r|^2 there."""
    r = W[_W_RG : _W_RG + 2]
    g = 0.5 * (math.sqrt(5.0) - 1.0)
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    z[0] = x1
    f1 = _evaluate(apex, a, z, u0, ints, floats, d, r, out)
    z[0] = x2
    f2 = _evaluate(apex, a, z, u0, ints, floats, d, r, out)
    for _ in range(_GOLDEN_ITER):
        if f1 <= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            z[0] = x1
            f1 = _evaluate(apex, a, z, u0, ints, floats, d, r, out)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            z[0] = x2
            f2 = _evaluate(apex, a, z, u0, ints, floats, d, r, out)
    z[0] = x1 if f1 <= f2 else x2
    return min(f1, f2)


@njit(error_model="numpy")
def _scan(apex, jac, a, z, u0, zlo, zhi, ints, floats, W, d, out, zbest, G):
    """The fallback of a one-control solve (or of a start where the map fails): scan the first
    control's range; one control and one target: the sign change nearest the start, solved by the
    Illinois method, or without one the closest point (golden section about the scan's best);
    otherwise Gauss-Newton again from the scan's best point. Returns |r|^2 of the result, whose
    controls are written into zbest."""
    n = ints[_I_SCAN]
    nc = ints[_I_NC]
    one = nc == 1 and ints[_I_TGT] + ints[_I_TGT + 1] == 1
    k = 0 if ints[_I_TGT] else 1
    r = W[_W_RS : _W_RS + 2]
    zs = W[_W_ZS : _W_ZS + 3]
    for j in range(nc):
        zs[j] = z[j]
    best = math.inf
    i_best = 0
    zb0 = z[0]
    prev_ok = False
    prev_z, prev_f = 0.0, 0.0
    bz_a, bz_b, bf_a, bf_b = 0.0, 0.0, 0.0, 0.0
    bracket_dist = math.inf
    start = z[0]
    step = (zhi[0] - zlo[0]) / (n - 1)
    for i in range(n):
        zs[0] = zlo[0] + step * i
        phi = _evaluate(apex, a, zs, u0, ints, floats, d, r, out)
        ok = phi < math.inf
        if ok and phi < best:
            best, zb0, i_best = phi, zs[0], i
        if ok and one:
            f = r[k]
            if prev_ok and (f < 0.0) != (prev_f < 0.0):
                dist = abs(0.5 * (prev_z + zs[0]) - start)
                if dist < bracket_dist:
                    bracket_dist = dist
                    bz_a, bz_b, bf_a, bf_b = prev_z, zs[0], prev_f, f
            prev_z, prev_f = zs[0], f
        prev_ok = ok
    if best == math.inf:
        return math.inf
    for j in range(nc):
        zbest[j] = z[j]
    if one and bracket_dist < math.inf:
        zbest[0] = bz_a
        return _illinois(apex, a, zbest, u0, ints, floats, W, d, out, bz_a, bz_b, bf_a, bf_b)
    if nc == 1:
        lo = zlo[0] + step * max(i_best - 1, 0)
        hi = zlo[0] + step * min(i_best + 1, n - 1)
        return _golden(apex, a, zbest, u0, ints, floats, W, d, out, lo, hi)
    zbest[0] = zb0
    return _gauss_newton(apex, jac, a, zbest, u0, zlo, zhi, ints, floats, W, d, out, G, _MAX_FAIL)


@njit(_SOLVE, cache=True, error_model="numpy")
def solve_row(apex, jac, a, ints, floats, W, out):
    """One deadbeat solve: the vector ``a`` holds the kernel's arguments (the apex, the ground, the
    parameters, the options and the starting controls at the controls' positions), then the target
    height and speed; ``W`` is the work buffer (:data:`N_WORK`, then room for the kernels' outputs);
    ``out`` gets the head (:data:`HEAD`) and the map's outputs at the final point (NaN when the map
    failed)."""
    nc = ints[_I_NC]
    n_out = ints[_I_NOUT]
    tol = floats[_F_TOL]
    for i in range(out.shape[0]):
        out[i] = _NAN
    out[_NJ] = 0.0
    out[_NE] = 0.0
    out[_NI] = 0.0
    d = W[N_WORK:]
    u0 = W[_W_U0 : _W_U0 + 3]
    z = W[_W_Z : _W_Z + 3]
    zlo = W[_W_ZLO : _W_ZLO + 3]
    zhi = W[_W_ZHI : _W_ZHI + 3]
    G = W[_W_G : _W_G + 6]
    for j in range(6):
        G[j] = _NAN
    for j in range(nc):
        u0[j] = a[ints[_I_ARG + j]]
        s = floats[_F_S + j]
        zlo[j] = (floats[_F_LO + j] - u0[j]) / s
        zhi[j] = (floats[_F_HI + j] - u0[j]) / s
        z[j] = min(max(0.0, zlo[j]), zhi[j])
    # one control: the scan is the safeguard, so Newton gets one failed line search
    max_fail = 1 if nc == 1 else _MAX_FAIL
    phi = _gauss_newton(apex, jac, a, z, u0, zlo, zhi, ints, floats, W, d, out, G, max_fail)
    first_status = int(d[0])
    m = ints[_I_TGT] + ints[_I_TGT + 1]
    # the scan: a start where the map fails, or one control that missed its target (or, least
    # squares, stopped on a failed line search rather than at a minimum)
    retry = phi == math.inf or (nc == 1 and phi > tol * tol and (m == 1 or W[_W_STALL] != 0.0))
    if retry and ints[_I_SCAN] >= 2:
        zb = W[_W_ZB : _W_ZB + 3]
        Gb = W[_W_GB : _W_GB + 6]
        for j in range(6):
            Gb[j] = _NAN
        phi_b = _scan(apex, jac, a, z, u0, zlo, zhi, ints, floats, W, d, out, zb, Gb)
        if phi_b < phi:
            phi = phi_b
            for j in range(nc):
                z[j] = zb[j]
            for j in range(6):
                G[j] = Gb[j]
    # the final point: the controls, the outputs, the residual, the energy authority
    _set_controls(a, z, u0, ints, floats)
    apex(a, d)
    out[_NE] += 1.0
    status = int(d[0])
    out[_MS] = float(status if phi < math.inf else first_status)
    for j in range(nc):
        out[_U0 + j] = a[ints[_I_ARG + j]]
    if status != _OK or phi == math.inf:
        out[_PS] = float(MAP_FAILED)
        if status == _OK:
            out[_MS] = float(first_status)
        return
    r = W[_W_RF : _W_RF + 2]
    phi = _residual(d, a, ints, floats, r)
    out[_RES] = math.sqrt(phi)
    out[_PS] = float(REACHED if phi <= tol * tol else UNREACHABLE)
    for j in range(n_out):
        out[N_HEAD + j] = d[1 + j]
    for j in range(nc):
        if ints[_I_COL + j] == ints[_I_KD]:
            v = d[1 + ints[_I_OV]]
            s = floats[_F_S + j]
            out[_AUTH] = floats[_F_M] * (floats[_F_G] * G[j] / s + v * G[3 + j] / s)
    # the energy budget: the next apex's energy with k_d at each bound, the other controls as found
    i_kd = ints[_I_KDARG]
    if i_kd >= 0:
        k_now = a[i_kd]
        for slot, k in ((_ELO, floats[_F_KDLO]), (_EHI, floats[_F_KDHI])):
            a[i_kd] = k
            apex(a, d)
            out[_NE] += 1.0
            if int(d[0]) == _OK:
                h, v = d[1 + ints[_I_OH]], d[1 + ints[_I_OV]]
                out[slot] = floats[_F_M] * (floats[_F_G] * h + 0.5 * v * v)
        a[i_kd] = k_now
        if math.isfinite(out[_ELO]) and math.isfinite(out[_EHI]):
            out[_AUTH] = (out[_EHI] - out[_ELO]) / (floats[_F_KDHI] - floats[_F_KDLO])
