"""The deadbeat solve compiled with numba: a bounded, safeguarded Gauss-Newton method on a map's kernels.

One generic solver (:func:`solve`) for every map. Its model is two role kernels of the map (the
generated index's ``apex_return`` and ``apex_return_jacobian``, or a decompression half's ``apex``
role: derive/ir.py, ``Layout``), taken as first-class functions of the one signature every role
kernel has, ``kernel(x, p, out) -> status`` (:data:`MODEL`): the controls are fields of the inputs
``x`` (the touchdown angle) or of the parameter record ``p`` (the stiffness), found by name in the
index's layouts (:class:`Settings`, built by :mod:`.deadbeat` and :mod:`.bottom`). A model without a
Jacobian kernel (a half map) gets its derivatives by central differences (``Settings.fd_step``).
Nothing here knows a map: the positions, the output columns and the Jacobian's columns come from the
generated index through :class:`~slipmaps.runtime.api.calls.Call`.

The solver is compiled once for every map and cached on disk like the kernels; the two entry points
bound to a map's kernels (:func:`bind`: a solve of one row and of many, releasing the GIL) are
compiled once per map and process (a few seconds: they link the map's kernels). A solve then costs
one call from Python and the map's kernel calls.

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
  closest reachable point of that neighbourhood: UNREACHABLE), or after ``max_evaluations`` map
  evaluations;
* one control (the touchdown angle alone, or k_d at the bottom): if that does not reach the target,
  a scan of the control's whole range (``scan`` points), then the sign change nearest the start
  bracketed and solved by the Illinois method (one target), or Gauss-Newton again from the scan's
  best point (two targets, least squares); the same scan restarts a solve whose start fails.

A solve's row (:data:`HEAD`, then the model's outputs at the final point) holds the plan status
(:data:`REACHED`, :data:`UNREACHABLE`, :data:`MAP_FAILED`) beside the map's own status there.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.experimental import structref
from slipmaps.generated.status import Status

__all__ = [
    "HEAD",
    "HEAD_AT",
    "MAP_FAILED",
    "MODEL",
    "REACHED",
    "UNREACHABLE",
    "Settings",
    "Solver",
    "bind",
]

#: Plan statuses as written by the solver (the Python layer's :class:`~.deadbeat.PlanStatus`).
REACHED, UNREACHABLE, MAP_FAILED = 0, 1, 2

#: The head of a solver row: its fields by name (then the model's outputs at the final point).
HEAD = (
    "plan_status",  # REACHED / UNREACHABLE / MAP_FAILED
    "map_status",  # the map's Status at the final point (or at the first failure)
    "jacobians",  # Jacobian evaluations (the generated kernel, or a central difference)
    "evaluations",  # map evaluations (line search, scan, bracketing)
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
#: The head's fields by name: their positions in a solver row (HEAD is their one definition).
HEAD_AT = {name: j for j, name in enumerate(HEAD)}
# the head's fields the solver writes (HEAD is their one definition)
_PS, _MS, _NJ, _NE, _NI, _U0, _RES, _AUTH, _ELO, _EHI = (
    HEAD_AT[name]
    for name in (
        "plan_status",
        "map_status",
        "jacobians",
        "evaluations",
        "iterations",
        "u0",
        "residual",
        "authority",
        "energy_low",
        "energy_high",
    )
)

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

#: A model: a role kernel, ``kernel(x, p, out) -> status`` (derive/ir.py's ``Layout``). Every map's
#: role kernels have this type, so the solver takes them as first-class functions and is compiled
#: (and cached on disk) once for every map.
_VEC = types.float64[::1]
MODEL = types.FunctionType(types.int64(_VEC, _VEC, _VEC))


# ----------------------------------------------------------------------------------------------
# The solver's settings and work space, by name
# ----------------------------------------------------------------------------------------------
@structref.register
class SettingsType(types.StructRef):
    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(t)) for name, t in fields)


class Settings(structref.StructRefProxy):
    """A solve's settings (built once per controller by :mod:`.deadbeat` or :mod:`.bottom`), every
    position found by name in the index's layouts:

    - the controls (at most 3): ``n_controls``; each control's place, in ``p`` (``in_p`` 1) or in
      ``x`` (0), at position ``pos``, its column ``col`` of the Jacobian, its bounds ``lo``,
      ``hi`` and scale ``scale`` (the scaled unknown is (u - u0) / scale);
    - the targets: ``targeted`` (1 for each of height, speed that is a target) and their residual
      weights ``weight``; ``tol`` on the scaled residual;
    - the model's row: its outputs ``n_out``, the Jacobian's inputs ``n_wrt`` (0 with
      ``fd_step`` > 0: central differences of relative step ``fd_step`` instead of a Jacobian
      kernel), the columns ``out_height`` and ``out_speed`` of the next apex;
    - k_d for the energy budget: its place (``kd_in_p``, ``kd_pos``; ``kd_pos`` -1 without k_d)
      and bounds ``kd_lo``, ``kd_hi``; the mass ``mass`` and ``g_f``;
    - the effort: ``max_evaluations``, ``broyden`` (1: secant updates), ``scan`` points.
    """

    def __new__(cls, **fields):
        unknown = sorted(set(fields) - set(SETTINGS))
        if unknown:
            raise TypeError(f"Settings has no field(s) {unknown}")
        values = []
        for name, kind in SETTINGS.items():
            v = fields[name]
            if isinstance(kind, types.Array):
                v = np.ascontiguousarray(v, dtype=np.int64 if kind.dtype == types.int64 else np.float64)
            else:
                v = int(v) if kind == types.int64 else float(v)
            values.append(v)
        return structref.StructRefProxy.__new__(cls, *values)


_I, _F, _IV, _FV = types.int64, types.float64, types.int64[::1], types.float64[::1]
#: The fields of :class:`Settings` and their types.
SETTINGS = {
    "n_controls": _I,
    "in_p": _IV,
    "pos": _IV,
    "col": _IV,
    "lo": _FV,
    "hi": _FV,
    "scale": _FV,
    "targeted": _IV,
    "weight": _FV,
    "tol": _F,
    "n_out": _I,
    "n_wrt": _I,
    "fd_step": _F,
    "out_height": _I,
    "out_speed": _I,
    "kd_in_p": _I,
    "kd_pos": _I,
    "kd_lo": _F,
    "kd_hi": _F,
    "mass": _F,
    "g_f": _F,
    "max_evaluations": _I,
    "broyden": _I,
    "scan": _I,
}
SETTINGS_TYPE = SettingsType(list(SETTINGS.items()))
structref.define_proxy(Settings, SettingsType, list(SETTINGS))


@structref.register
class WorkType(types.StructRef):
    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(t)) for name, t in fields)


class Work(structref.StructRefProxy):
    """A solve's work space (made in compiled code by :func:`_work`)."""


#: The fields of :class:`Work`: the row's inputs ``x``, its parameter record ``p`` (copies the
#: solve changes), the targets, the model's rows: ``d`` a Jacobian's, ``v`` the values at the last
#: evaluation, ``e`` another (a central difference's, the energy budget's); the controls' start
#: ``u0``, the scaled controls ``z`` and their bounds, the Jacobian of (height, speed) by the scaled
#: controls ``G`` (2 x 3 row-major) and its weighted form ``J``, the residuals, the steps' vectors
#: and a 3 x 3 system ``A``, ``b``, and ``stall`` (1 when the last Gauss-Newton run ended on a
#: failed line search or its budget).
WORK = (
    "x",
    "p",
    "target",
    "d",
    "v",
    "e",
    "u0",
    "z",
    "zlo",
    "zhi",
    "G",
    "zb",
    "Gb",
    "rf",
    "J",
    "r",
    "rt",
    "F",
    "delta",
    "zt",
    "free",
    "A",
    "b",
    "rows",
    "cols",
    "zs",
    "rs",
    "ri",
    "rg",
    "stall",
)
structref.define_proxy(Work, WorkType, list(WORK))


@njit(error_model="numpy")
def _work(nx, np_, n_out, width):
    """A work space for rows of ``nx`` inputs, ``np_`` parameters, ``n_out`` outputs of the model
    and its Jacobian's rows of ``width``."""
    v = np.empty
    return Work(
        v(nx), v(np_), v(2), v(width), v(n_out), v(n_out), v(3), v(3), v(3), v(3), v(6), v(3), v(6), v(2),
        v(6), v(2), v(2), v(2), v(3), v(3), v(3), v(9), v(3), v(2), v(3), v(3), v(2), v(2), v(2), 0.0,
    )  # fmt: skip


# ----------------------------------------------------------------------------------------------
# The numerics
# ----------------------------------------------------------------------------------------------
@njit(error_model="numpy")
def _residual(d, s, w, r):
    """r (2) from the model's outputs d: weight (F - T) for the targeted components, 0 for the
    others; returns |r|^2."""
    h = d[s.out_height]
    v = d[s.out_speed]
    r[0] = s.weight[0] * (h - w.target[0]) if s.targeted[0] else 0.0
    r[1] = s.weight[1] * (v - w.target[1]) if s.targeted[1] else 0.0
    return r[0] * r[0] + r[1] * r[1]


@njit(error_model="numpy")
def _set(w, in_p, pos, value):
    """A control's value into the row's inputs or its parameter record."""
    if in_p:
        w.p[pos] = value
    else:
        w.x[pos] = value


@njit(error_model="numpy")
def _get(w, in_p, pos):
    return w.p[pos] if in_p else w.x[pos]


@njit(error_model="numpy")
def _set_controls(s, w, z):
    for j in range(s.n_controls):
        _set(w, s.in_p[j], s.pos[j], w.u0[j] + s.scale[j] * z[j])


@njit(error_model="numpy")
def _weighted(G, s, J):
    """J = d r / d z: the rows of G weighted, zero for a component that is not a target."""
    for j in range(s.n_controls):
        J[j] = s.weight[0] * G[j] if s.targeted[0] else 0.0
        J[3 + j] = s.weight[1] * G[3 + j] if s.targeted[1] else 0.0


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
def _evaluate(apex, s, w, z, r, out):
    """The map at controls z into w.v: |r|^2, or inf when the map fails there (w.rf[0] holds its
    status)."""
    _set_controls(s, w, z)
    code = apex(w.x, w.p, w.v)
    out[_NE] += 1.0
    w.rf[0] = code
    if code != _OK:
        return math.inf
    return _residual(w.v, s, w, r)


@njit(error_model="numpy")
def _fresh(apex, jac, s, w, z, out, G):
    """A Jacobian of the map at z into G (d (height, speed) / d z_j), the values into w.v; False
    when the map (or its derivative) fails there. With ``s.fd_step`` > 0, central differences of
    the map in each control."""
    _set_controls(s, w, z)
    out[_NJ] += 1.0
    if s.fd_step <= 0.0:
        code = jac(w.x, w.p, w.d)
        w.rf[0] = code
        if code != _OK:
            return False
        n_out, n_wrt = s.n_out, s.n_wrt
        for i in range(n_out):
            w.v[i] = w.d[i]
        for j in range(s.n_controls):
            col = s.col[j]
            G[j] = w.d[n_out + s.out_height * n_wrt + col] * s.scale[j]
            G[3 + j] = w.d[n_out + s.out_speed * n_wrt + col] * s.scale[j]
        return True
    for j in range(s.n_controls):
        u = _get(w, s.in_p[j], s.pos[j])
        h = s.fd_step * max(abs(u), s.scale[j] * 1e-3)
        _set(w, s.in_p[j], s.pos[j], u + h)
        code = apex(w.x, w.p, w.e)
        hp, vp = w.e[s.out_height], w.e[s.out_speed]
        _set(w, s.in_p[j], s.pos[j], u - h)
        other = apex(w.x, w.p, w.e)
        _set(w, s.in_p[j], s.pos[j], u)
        if code != _OK or other != _OK:
            w.rf[0] = code if code != _OK else other
            return False
        G[j] = (hp - w.e[s.out_height]) / (2.0 * h) * s.scale[j]
        G[3 + j] = (vp - w.e[s.out_speed]) / (2.0 * h) * s.scale[j]
    code = apex(w.x, w.p, w.v)
    w.rf[0] = code
    return code == _OK


@njit(error_model="numpy")
def _gauss_newton(apex, jac, s, w, z, out, G, max_fail):
    """Bounded, line-searched Gauss-Newton from z (updated in place; G holds the last Jacobian,
    dF/dz); at most ``max_fail`` failed line searches. Returns |r|^2 at the end (inf when the map
    fails at the start: w.rf[0] holds its status)."""
    nc = s.n_controls
    m = s.targeted[0] + s.targeted[1]
    tol2 = s.tol**2
    broyden = s.broyden != 0
    J, r, rt, F, delta, zt, free = w.J, w.r, w.rt, w.F, w.delta, w.zt, w.free
    zlo, zhi = w.zlo, w.zhi
    for i in range(6):
        J[i] = 0.0
    w.stall = 1.0
    if not _fresh(apex, jac, s, w, z, out, G):
        return math.inf
    phi = _residual(w.v, s, w, r)
    F[0], F[1] = w.v[s.out_height], w.v[s.out_speed]
    fresh = True
    damping = 0  # rounds of growing mu since the last accepted step
    fails = 0
    while True:
        _weighted(G, s, J)
        # free controls: not held at a bound by the descent direction -J^T r
        scale = 0.0
        for j in range(nc):
            gj = J[j] * r[0] + J[3 + j] * r[1]
            held = (z[j] <= zlo[j] and gj > 0.0) or (z[j] >= zhi[j] and gj < 0.0)
            free[j] = 0.0 if held else 1.0
            scale += J[j] ** 2 + J[3 + j] ** 2
        mu = 0.0 if damping == 0 else scale * 1e-3 * 100.0 ** (damping - 1)
        if not _step(w.A, w.b, w.rows, w.cols, J, r, z, free, nc, mu, delta):
            if damping < _DAMPING_ROUNDS:
                damping += 1
                continue
            break
        # converged: the residual within tol and (more controls than targets) the pull at rest
        size = 0.0
        for j in range(nc):
            size = max(size, abs(delta[j]))
        if phi <= tol2 and (size <= _PULL_TOL or nc <= m):
            w.stall = 0.0
            break
        if phi <= tol2 and not fresh:  # the pull toward the start needs the null space exactly
            if not _fresh(apex, jac, s, w, z, out, G):
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
                if not _fresh(apex, jac, s, w, z, out, G):
                    break
                fresh = True
                continue
            w.stall = 0.0
            break
        # Armijo's condition on the decrease the linearised residual promises (a strict decrease)
        decrease = max(phi - pred, 0.0)
        alpha = 1.0
        accepted = False
        phi_t = math.inf
        for _ in range(_HALVINGS if fresh else _SECANT_HALVINGS):
            for j in range(nc):
                zt[j] = min(max(z[j] + alpha * delta[j], zlo[j]), zhi[j])
            phi_t = _evaluate(apex, s, w, zt, rt, out)
            if (phi_t < phi and phi_t <= phi - _ARMIJO * alpha * decrease) or (phi <= tol2 and phi_t <= tol2):
                accepted = True
                break
            alpha *= 0.5
        if not accepted:
            if fresh and phi - pred <= _FLAT * phi:  # no decrease left to find: a minimum
                w.stall = 0.0
                break
            fails += 1
            if fails > max_fail:
                break
            if not fresh:  # a secant Jacobian may be off: a fresh one before giving up
                if not _fresh(apex, jac, s, w, z, out, G):
                    break
                fresh = True
                continue
            if damping < _DAMPING_ROUNDS:  # damp toward the gradient direction
                damping += 1
                continue
            break
        out[_NI] += 1.0
        damping = 0
        ht, vt = w.v[s.out_height], w.v[s.out_speed]
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
        if out[_NJ] + out[_NE] >= s.max_evaluations:
            break
        if not broyden:
            if not _fresh(apex, jac, s, w, z, out, G):
                break  # the values just succeeded: a derivative that does not exist
            fresh = True
    return phi


@njit(error_model="numpy")
def _illinois(apex, s, w, z, out, za, zb, fa, fb):
    """The one-control, one-target root in the bracket [za, zb] (f(za) f(zb) < 0) by the Illinois
    method; z[0] set to it; returns |r|^2 there."""
    r = w.ri
    k = 0 if s.targeted[0] else 1
    tol = s.tol
    side = 0
    phi = math.inf
    for _ in range(_BRACKET_ITER):
        zc = (za * fb - zb * fa) / (fb - fa)
        if not (min(za, zb) < zc < max(za, zb)):
            zc = 0.5 * (za + zb)
        z[0] = zc
        phi = _evaluate(apex, s, w, z, r, out)
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
def _golden(apex, s, w, z, out, lo, hi):
    """The minimum of |r|^2 over the first control in [lo, hi] (golden section, a failing map
    counting as inf); z[0] set to it; returns |r|^2 there."""
    r = w.rg
    g = 0.5 * (math.sqrt(5.0) - 1.0)
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    z[0] = x1
    f1 = _evaluate(apex, s, w, z, r, out)
    z[0] = x2
    f2 = _evaluate(apex, s, w, z, r, out)
    for _ in range(_GOLDEN_ITER):
        if f1 <= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            z[0] = x1
            f1 = _evaluate(apex, s, w, z, r, out)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            z[0] = x2
            f2 = _evaluate(apex, s, w, z, r, out)
    z[0] = x1 if f1 <= f2 else x2
    return min(f1, f2)


@njit(error_model="numpy")
def _scan(apex, jac, s, w, z, out, zbest, G):
    """The fallback of a one-control solve (or of a start where the map fails): scan the first
    control's range; one control and one target: the sign change nearest the start, solved by the
    Illinois method, or without one the closest point (golden section about the scan's best);
    otherwise Gauss-Newton again from the scan's best point. Returns |r|^2 of the result, whose
    controls are written into zbest."""
    n = s.scan
    nc = s.n_controls
    one = nc == 1 and s.targeted[0] + s.targeted[1] == 1
    k = 0 if s.targeted[0] else 1
    r, zs, zlo, zhi = w.rs, w.zs, w.zlo, w.zhi
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
        phi = _evaluate(apex, s, w, zs, r, out)
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
        return _illinois(apex, s, w, zbest, out, bz_a, bz_b, bf_a, bf_b)
    if nc == 1:
        lo = zlo[0] + step * max(i_best - 1, 0)
        hi = zlo[0] + step * min(i_best + 1, n - 1)
        return _golden(apex, s, w, zbest, out, lo, hi)
    zbest[0] = zb0
    return _gauss_newton(apex, jac, s, w, zbest, out, G, _MAX_FAIL)


@njit(error_model="numpy")
def solve(apex, jac, x, p, target, s, w, out):
    """One deadbeat solve: from the row's inputs ``x`` and parameter record ``p`` (the starting
    controls at their places) to the ``target`` next apex (height, speed), with settings ``s`` and
    work space ``w`` (:func:`_work`); ``out`` gets the head (:data:`HEAD`) and the model's outputs
    at the final point (NaN when the map failed)."""
    nc = s.n_controls
    n_out = s.n_out
    tol = s.tol
    for i in range(x.shape[0]):
        w.x[i] = x[i]
    for i in range(p.shape[0]):
        w.p[i] = p[i]
    w.target[0], w.target[1] = target[0], target[1]
    for i in range(out.shape[0]):
        out[i] = _NAN
    out[_NJ] = 0.0
    out[_NE] = 0.0
    out[_NI] = 0.0
    u0, z, zlo, zhi, G = w.u0, w.z, w.zlo, w.zhi, w.G
    for j in range(6):
        G[j] = _NAN
    for j in range(nc):
        u0[j] = _get(w, s.in_p[j], s.pos[j])
        zlo[j] = (s.lo[j] - u0[j]) / s.scale[j]
        zhi[j] = (s.hi[j] - u0[j]) / s.scale[j]
        z[j] = min(max(0.0, zlo[j]), zhi[j])
    # one control: the scan is the safeguard, so Newton gets one failed line search
    max_fail = 1 if nc == 1 else _MAX_FAIL
    phi = _gauss_newton(apex, jac, s, w, z, out, G, max_fail)
    first_status = int(w.rf[0])
    m = s.targeted[0] + s.targeted[1]
    # the scan: a start where the map fails, or one control that missed its target (or, least
    # squares, stopped on a failed line search rather than at a minimum)
    retry = phi == math.inf or (nc == 1 and phi > tol * tol and (m == 1 or w.stall != 0.0))
    if retry and s.scan >= 2:
        zb, Gb = w.zb, w.Gb
        for j in range(6):
            Gb[j] = _NAN
        phi_b = _scan(apex, jac, s, w, z, out, zb, Gb)
        if phi_b < phi:
            phi = phi_b
            for j in range(nc):
                z[j] = zb[j]
            for j in range(6):
                G[j] = Gb[j]
    # the final point: the controls, the outputs, the residual, the energy authority
    _set_controls(s, w, z)
    status = apex(w.x, w.p, w.v)
    out[_NE] += 1.0
    out[_MS] = float(status if phi < math.inf else first_status)
    for j in range(nc):
        out[_U0 + j] = _get(w, s.in_p[j], s.pos[j])
    if status != _OK or phi == math.inf:
        out[_PS] = float(MAP_FAILED)
        if status == _OK:
            out[_MS] = float(first_status)
        return
    r = w.rf
    phi = _residual(w.v, s, w, r)
    out[_RES] = math.sqrt(phi)
    out[_PS] = float(REACHED if phi <= tol * tol else UNREACHABLE)
    for j in range(n_out):
        out[N_HEAD + j] = w.v[j]
    v_now = w.v[s.out_speed]
    for j in range(nc):
        if s.kd_pos >= 0 and s.in_p[j] == s.kd_in_p and s.pos[j] == s.kd_pos:
            out[_AUTH] = s.mass * (s.g_f * G[j] / s.scale[j] + v_now * G[3 + j] / s.scale[j])
    # the energy budget: the next apex's energy with k_d at each bound, the other controls as found
    if s.kd_pos >= 0:
        k_now = _get(w, s.kd_in_p, s.kd_pos)
        for slot, k in ((_ELO, s.kd_lo), (_EHI, s.kd_hi)):
            _set(w, s.kd_in_p, s.kd_pos, k)
            code = apex(w.x, w.p, w.e)
            out[_NE] += 1.0
            if code == _OK:
                h, v = w.e[s.out_height], w.e[s.out_speed]
                out[slot] = s.mass * (s.g_f * h + 0.5 * v * v)
        _set(w, s.kd_in_p, s.kd_pos, k_now)
        if math.isfinite(out[_ELO]) and math.isfinite(out[_EHI]):
            out[_AUTH] = (out[_EHI] - out[_ELO]) / (s.kd_hi - s.kd_lo)


_MAT = types.float64[:, ::1]


@njit(
    types.void(MODEL, MODEL, _MAT, _MAT, _MAT, SETTINGS_TYPE, _MAT),
    cache=True,
    error_model="numpy",
    nogil=True,
)
def solve_rows(apex, jac, X, P, T, s, OUT):
    """:func:`solve` for every row of ``X`` (``P`` one parameter record for every row or one per
    row, ``T`` the targets), one work space for all."""
    w = _work(X.shape[1], P.shape[1], s.n_out, s.n_out * (1 + s.n_wrt))
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        solve(apex, jac, X[i], P[min(i, last)], T[i], s, w, OUT[i])


_BOUND: dict = {}


def bind(apex, jac):
    """The solver bound to one model's role kernels (``jac`` the Jacobian kernel, or ``apex`` again
    with ``Settings.fd_step`` > 0): ``rows(X, P, T, s, OUT)``, compiled once per model and process
    (numba types the two kernels as constants), releasing the GIL."""
    hit = _BOUND.get((apex, jac))
    if hit is not None:
        return hit

    @njit(error_model="numpy", nogil=True)
    def rows(X, P, T, s, OUT):
        solve_rows(apex, jac, X, P, T, s, OUT)

    _BOUND[(apex, jac)] = rows
    return rows


class Solver:
    """The solver on a model: the role kernel ``apex`` and its Jacobian ``jac`` (index specs:
    :class:`~slipmaps.runtime.api.index.KernelSpec`), or without ``jac`` central differences of
    ``apex``. Its :meth:`place` finds a quantity in the model's layouts by name, :meth:`settings`
    builds the settings, :meth:`run` solves rows."""

    def __init__(self, apex, jac=None):
        self.x, self.p, self.outputs = apex.x, apex.p, apex.outputs
        self.wrt = jac.wrt if jac is not None else ()
        if jac is not None and (jac.x, jac.p) != (apex.x, apex.p):
            raise RuntimeError(f"{apex.name} and {jac.name} take different layouts")
        f = apex.functions()[0]
        self._rows = bind(f, f if jac is None else jac.functions()[0])

    @property
    def width(self) -> int:
        """A solve's row: :data:`HEAD`, then the model's outputs."""
        return N_HEAD + len(self.outputs)

    def place(self, name: str) -> tuple[int, int]:
        """(1, position in ``p``) or (0, position in ``x``) of a quantity, by its name."""
        if name in self.x:
            return 0, self.x.index(name)
        return 1, self.p.index(name)

    def settings(
        self,
        controls,
        lo,
        hi,
        scale,
        *,
        targeted,
        fd_step=0.0,
        kd=None,
        kd_bounds,
        targets=("apex_height", "apex_speed"),
        **fields,
    ):
        """:class:`Settings` for the ``controls`` (names of the model's inputs or parameters) with
        their bounds ``lo``, ``hi`` and scales, the ``targeted`` components, k_d (the name of the
        energy budget's stiffness, None for none) and its bounds; ``targets``: the model's two
        outputs the targets are of (the next apex's height and speed; the footholds' baseline aims
        the foot, ``foot_x``, and the speed); ``fields`` the rest."""
        places = [self.place(c) for c in controls]
        pad = 3 - len(controls)
        kd_place = self.place(kd) if kd is not None else (1, -1)
        return Settings(
            n_controls=len(controls),
            in_p=[p[0] for p in places] + [0] * pad,
            pos=[p[1] for p in places] + [0] * pad,
            col=[self.wrt.index(c) if c in self.wrt else -1 for c in controls] + [0] * pad,
            lo=list(lo) + [0.0] * pad,
            hi=list(hi) + [0.0] * pad,
            scale=list(scale) + [1.0] * pad,
            targeted=list(targeted),
            n_out=len(self.outputs),
            n_wrt=len(self.wrt),
            fd_step=fd_step,
            out_height=self.outputs.index(targets[0]),
            out_speed=self.outputs.index(targets[1]),
            kd_in_p=kd_place[0],
            kd_pos=kd_place[1],
            kd_lo=kd_bounds[0],
            kd_hi=kd_bounds[1],
            **fields,
        )

    def run_one(self, x, p, t, settings) -> np.ndarray:
        """One solve, here (a scalar plan: no blocks, no threads): the row (:attr:`width`) from the
        inputs ``x`` (1, len(x)), one parameter record ``p`` (1, len(p)) and the targets ``t``
        (1, 2)."""
        out = np.empty((1, self.width))
        self._rows(x, p, t, settings, out)
        return out[0]

    def run(self, X, P, T, settings) -> np.ndarray:
        """Solve every row: inputs ``X`` (n, len(x)), parameter records ``P`` (1 or n rows),
        targets ``T`` (n, 2): the rows (n, :attr:`width`)."""
        from ..api.batch import BatchInterrupted, run_blocks

        n = X.shape[0]
        OUT = np.empty((n, self.width))
        shared = P.shape[0] == 1

        def block(lo, hi):
            self._rows(X[lo:hi], P if shared else P[lo:hi], T[lo:hi], settings, OUT[lo:hi])

        try:
            run_blocks(block, n, self._rows)
        except BatchInterrupted as stop:  # Ctrl-C: the rows finished
            stop.result = OUT[: stop.done]
            raise
        return OUT
