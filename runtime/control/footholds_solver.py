"""The footholds least squares compiled with numba: the controls of the next H hops over the stone
sequences within reach, on a map's generated apex-return Jacobian (:mod:`.footholds` prepares and
reads it). One call plans an apex (:func:`plan_rows`):

1. the candidate sequences (k_1, ..., k_H) of the stones seen (rows ``first`` to ``last`` - 1 of the
   stones' table, :data:`STONE`), in order, a stone taking two feet at most where it is long enough:
   the first foot within ``reach`` of the ``aim`` (the neutral foothold), each next one a nominal
   ``step`` on within ``reach`` (by the stones' usable parts);
2. each sequence's least squares, in two phases: every sequence :data:`SCREEN` iterations, then to
   convergence (or ``max_iter``) those whose cost is within :data:`SCREEN_GAP` of the best (a
   sequence whose feet stay several stones off is dropped early);
3. the choice: the sequence of least cost among the feasible ones (every hop's map OK, every foot
   inside its stone's usable part, every hop clear of the stones it passes, every next apex moving
   in the target's direction and rising from its liftoff for at least half of ``t_min``), else the
   least-cost one that ran (``RES``: :data:`RESULTS`).

The problem of a sequence. The unknowns are the controls u of every hop (the touchdown angle, and
k_d or k_c or k: ``nc`` a hop, H nc in all); the hops are chained, the next apex of hop i (its
height above stone k_i, its speed, its x: the apex's x plus the step length) the apex of hop i + 1,
each on the ground of its stone relative to the last one. The residuals, :data:`PER_HOP` a hop and
one a control:

* the foot: w_foot (x_foot - c_k) / half_k, the foot's x (the apex's x plus the map's ``foot_x``)
  against the centre c_k of the stone's usable part in units of its half-width: 0 at the centre, 1 at
  the usable part's end (the least squares keeps every foot as deep inside its stone as the hop
  allows);
* the next apex: w_height (h - H_i) / l0 and w_speed (v - V_i) / sqrt(g_f l0), against the nominal
  target of that step (the deadbeat's scaling);
* viability, hinges that are 0 where they hold: the floor, w_floor max(0, floor + rise - h) / l0
  (the apex at least ``floor`` above the next stone, ``rise`` its height above this one; after the
  last hop, the stone after k_H); the rise after liftoff, w_floor max(0, t_min - t_ascent) / t_min
  (a hop at the edge of LIFTOFF_DOWNWARD on the model may fail on the plant); the clearance,
  w_floor max(0, s + c) / c with c = :data:`CLEARANCE` l0 and s the most by which the falling foot
  is short of the end of a higher stone it passes when it comes down to that stone's height (the
  model's exact flight, ``apex_to_touchdown``; its derivatives by forward differences);
* the least change: w_reg (u - u_nom) / s, each control against its nominal value (the neutral angle,
  the nominal stiffness) in the deadbeat's scaled norm (s: :data:`~.deadbeat.ANGLE_SCALE` for the
  angle, the nominal k_c for a stiffness), so that controls to spare (k_c and k_d both) take the
  least change, as the deadbeat's null-space pull does.

The Jacobian is exact: each hop's generated derivatives (d/d apex height, d/d apex speed, d/d each
control) chained forward through the apex states (forward mode over the hops). The start
(:func:`_aim`): each hop's angle puts its foot into its stone (the point of the usable part's inner
half nearest where the hop's starting angle puts it) and its stiffness gives the next apex the
target's energy (Newton's method on the map's outputs), hop after hop; the hops the last plan
continues start from its controls instead (model-predictive warm start). The method:
Levenberg-Marquardt in the scaled unknowns (u - u_nom) / s' (s': 1 rad, the nominal k_c), Nielsen's
damping update, every trial point projected into the controls' bounds with an active set (a control
at a bound whose descent leaves the box is held there for the step), a trial where a hop's map fails
counting as no decrease; a sequence has converged when a step changes the scaled controls by less
than 1e-7 or the cost by less than ``tol`` of itself.

Why not the deadbeat's solver (:mod:`.compiled`): that solves one step, at most three controls and
the two components of one next apex, in work arrays of that size, with one-control fallbacks (a
scan, Illinois) that a chain of hops has no use for; the footholds problem has up to nine unknowns
and 6 H + 9 residuals through H chained map calls, and a replan solves several. SciPy's
``least_squares`` would serve for one sequence, but its Python costs more than a replan's budget:
2.2 ms a solve with bounds (``trf``), 0.5 ms without (``lm``), on a problem of 4 unknowns and 21
residuals that takes 5 evaluations (callbacks in numpy, nothing of a map; 2-core AMD EPYC under
load); compiled, one call enumerates, solves and chooses. This is the one implementation: the
planner, the runs' ``footholds`` policy, the study and the benchmark all call it through
:class:`.footholds.Footholds`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types

from .compiled import MODEL

__all__ = ["CF", "CI", "HOP", "MAX_SEQUENCES", "OUT_HEAD", "RESULTS", "STONE", "bind", "out_width"]

#: The integer settings ``ci`` by name (positions in the row ``x``, the outputs and the Jacobian's
#: columns; the iterations; the control that changes the energy, -1 for none; the descent kernel's
#: row length, its inputs' positions, its foot's output and its width).
CI = (
    "nc",
    "n_out",
    "n_wrt",
    "o_h",
    "o_v",
    "o_l",
    "o_f",
    "x_h",
    "x_v",
    "x_th",
    "x_g",
    "w_h",
    "w_v",
    "max_iter",
    "ce",
    "o_ta",
    "d_nx",
    "d_h",
    "d_v",
    "d_th",
    "d_qr",
    "d_gf",
    "d_g",
    "d_rate",
    "d_foot",
    "d_width",
)
#: The float settings ``cf`` by name: the apex's x and ground, the weights, the scales, the floor,
#: the tolerance, gravity and the touchdown leg length, the enumeration's aim, reach and step.
CF = (
    "x0",
    "g0",
    "w_foot",
    "w_height",
    "w_speed",
    "w_floor",
    "w_reg",
    "l0",
    "v_scale",
    "floor",
    "tol",
    "g_f",
    "q_r_td",
    "aim",
    "reach",
    "step",
    "t_min",
    "margin",
    "first",
)
#: A stone's row in the stones' table: its usable part's ends, centre and half-width, its height,
#: and the height of the stone after it (the floor after a sequence's last hop).
STONE = ("lo", "hi", "centre", "half", "height", "next_height")
#: A sequence's row of OUT: this head, then per hop :data:`HOP`, then the controls (H nc).
OUT_HEAD = ("status", "cost", "iterations", "evaluations", "converged", "feasible")
HOP = ("foot", "margin", "apex_height", "apex_speed", "apex_x", "t_ascent", "shortfall")
#: ``RES`` of a plan: the sequences found, the chosen one's row, and the outcome: 0 a feasible
#: sequence, 1 none feasible (the least-cost one that ran), 2 the map failed on every one, 3 no
#: sequence within reach.
RESULTS = ("count", "best", "outcome")
#: Sequences a plan solves at most (the nearest first).
MAX_SEQUENCES = 96

(_NC, _NOUT, _NWRT, _OH, _OV, _OL, _OF, _XH, _XV, _XTH, _XG, _WH, _WV, _MAXIT, _CE, _OTA) = range(16)
_DNX, _DH, _DV, _DTH, _DQR, _DGF, _DG, _DRATE, _DFOOT, _DWIDTH = range(16, len(CI))
_X0, _G0, _WFOOT, _WHEIGHT, _WSPEED, _WFLOOR, _WREG, _L0, _VS, _FLOOR, _TOL, _GF, _QR = range(13)
_AIMX, _REACH, _STEP, _TMIN, _MARGINX, _FIRST = range(13, len(CF))
_LO, _HI, _CENTRE, _HALF, _HEIGHT, _NEXT = range(len(STONE))
_STATUS, _COST, _ITER, _EVAL, _CONV, _FEAS = range(len(OUT_HEAD))
_FOOT, _MARGIN, _APH, _APV, _APX, _TA, _CLEAR = range(len(HOP))
_NH = len(OUT_HEAD)
_NHOP = len(HOP)
_OK = 0
#: Residuals a hop has before the least-change ones.
PER_HOP = 6
#: The step [rad, m, m/s] of the descent's forward differences (the clearance's derivatives).
FD_STEP = 1e-7
#: The clearance [l0] the least squares keeps between the foot and a higher stone's end it passes
#: (its residual grows from there, per this much shortfall).
CLEARANCE = 0.03
#: Newton steps at most of a starting angle (:func:`_aim`).
AIM_STEPS = 4
#: A starting angle at least this far [rad] beyond the least at which the leg reaches the ground.
AIM_CLEARANCE = 0.05
#: The first phase's iterations, and the cost above the best beyond which a sequence stops there
#: (1: one foot at the end of its usable part).
SCREEN = 5
SCREEN_GAP = 1.0


def out_width(hops: int, nc: int) -> int:
    """The length of a sequence's row of OUT."""
    return _NH + hops * (_NHOP + nc)


# ----------------------------------------------------------------------------------------------
# A problem ``prob`` is the tuple (stones, nominal, x0, p0, ci, ctl_i, ctl_f, cf): the stones'
# table (:data:`STONE`), each hop's target (height, speed), the first hop's input row and the
# parameter record, the settings (:data:`CI`), the controls' places (in p or x, position, Jacobian
# column; 3 x nc) and values (lower and upper bounds, nominal, least-change scale, step scale;
# 5 x nc), the settings (:data:`CF`). The work arrays ``w`` (:func:`_work`): the row x, the record p,
# a kernel's row d, the chain's derivatives D and E, the residuals and their Jacobian (r, J; rt,
# Jt at a trial), the normal matrix A, the gradient g, the step delta, the trial controls ut, the
# hops' values (hops; hopt at a trial), the free controls, a copy of the controls (keep), the
# clearance's derivatives (C), and the descent kernel's row and outputs (dx, dout).
# ----------------------------------------------------------------------------------------------
@njit(error_model="numpy")
def _put(x, p, ctl_i, c, value):
    """Control ``c``'s value into the row ``x`` or the record ``p``."""
    if ctl_i[0, c]:
        p[ctl_i[1, c]] = value
    else:
        x[ctl_i[1, c]] = value


@njit(error_model="numpy")
def _take(x, p, ctl_i, c):
    """Control ``c``'s value in the row ``x`` or the record ``p``."""
    return p[ctl_i[1, c]] if ctl_i[0, c] else x[ctl_i[1, c]]


@njit(error_model="numpy")
def _hop_inputs(i, seq, u, h, v, gprev, prob, x, p):
    """Hop ``i``'s row ``x`` and record ``p``: from the apex (``h``, ``v``) over the ground
    ``gprev`` (absolute) onto stone seq[i], with its controls of ``u``."""
    stones, _, x0, p0, ci, ctl_i = prob[0], prob[1], prob[2], prob[3], prob[4], prob[5]
    nc = ci[_NC]
    for j in range(x.shape[0]):
        x[j] = x0[j]
    for j in range(p.shape[0]):
        p[j] = p0[j]
    x[ci[_XH]] = h
    x[ci[_XV]] = v
    x[ci[_XG]] = stones[seq[i], _HEIGHT] - gprev
    for c in range(nc):
        _put(x, p, ctl_i, c, u[i * nc + c])


@njit(error_model="numpy")
def _d(d, ci, o, w):
    """d output ``o`` / d input ``w`` in a Jacobian kernel's row ``d``."""
    return d[ci[_NOUT] + o * ci[_NWRT] + w]


@njit(error_model="numpy")
def _foot_at(descent, dx, dout, ci, cf, ground, X):
    """The foot's x [m] when it falls to ``ground`` (relative to the apex's) from the apex in ``dx``
    (the model's exact flight), or where it is below that already at the apex, its x there; and
    whether the flight ran."""
    dx[ci[_DG]] = ground
    if descent(dx, dx, dout) == _OK:
        return X + dout[ci[_DFOOT]], True
    return X + cf[_QR] * math.sin(dx[ci[_DTH]]), False


@njit(error_model="numpy")
def _clearance(descent, i, seq, u, h, v, X, gprev, start, prob, w, want):
    """Hop ``i``'s clearance shortfall [m]: over the stones from ``start`` to its own that stand
    higher than its own, the most by which the falling foot is short of a stone's end (its usable
    end plus the margin) when it comes down to that stone's height (the model's exact flight
    ``apex_to_touchdown``; where the foot is below that height at the apex already, its x there);
    at most 0 when the hop clears them. With ``want``, the derivatives of that foot's x by the
    apex height, speed and the angle (forward differences of the flight) into ``w[17]``, and the
    angle's control there too."""
    stones, ci, ctl_i, cf = prob[0], prob[4], prob[5], prob[7]
    dx, dout, C = w[18], w[19], w[17]
    nc = ci[_NC]
    k = seq[i]
    ca = 0
    for c in range(nc):
        if ctl_i[0, c] == 0 and ctl_i[1, c] == ci[_XTH]:
            ca = c
    th = u[i * nc + ca]
    dx[:] = 0.0
    dx[ci[_DQR]], dx[ci[_DGF]] = cf[_QR], cf[_GF]
    worst = -math.inf
    for j in range(start, k):
        end = stones[j, _HI] + cf[_MARGINX]  # the stone's end: its usable part's, and the margin
        if stones[j, _HEIGHT] <= stones[k, _HEIGHT] or end <= X:
            continue
        dx[ci[_DH]], dx[ci[_DV]], dx[ci[_DTH]] = h, v, th
        ground = stones[j, _HEIGHT] - gprev
        foot, flew = _foot_at(descent, dx, dout, ci, cf, ground, X)
        if end - foot <= worst:
            continue
        worst = end - foot
        if want:
            C[3] = ca
            if not flew:
                C[0], C[1], C[2] = 0.0, 0.0, cf[_QR] * math.cos(th)
                continue
            for e in range(3):
                at = ci[_DH] if e == 0 else (ci[_DV] if e == 1 else ci[_DTH])
                dx[at] += FD_STEP
                moved, ok = _foot_at(descent, dx, dout, ci, cf, ground, X)
                dx[at] -= FD_STEP
                C[e] = (moved - foot) / FD_STEP if ok else 0.0
    return worst if worst > -math.inf else -1.0


@njit(error_model="numpy")
def _chain(kernels, want, u, seq, prob, w, r, J, hops):
    """The hops of ``seq`` at the controls ``u``: the residuals ``r`` (module docstring), with
    ``want`` their Jacobian ``J`` (m x n) by u, and each hop's foot, next apex, ascent time and
    clearance shortfall in ``hops``; returns 0, or the status of the first hop whose map fails."""
    apex, jac = kernels[0], kernels[1]
    stones, nominal, x0, _, ci, ctl_i, ctl_f, cf = prob
    x, p, d, D, E, C = w[0], w[1], w[2], w[3], w[4], w[17]
    H = seq.shape[0]
    nc = ci[_NC]
    n = H * nc
    outs = (ci[_OF], ci[_OH], ci[_OV], ci[_OL], ci[_OTA])  # E's rows: foot, h, v, step, ascent
    wh, wv = ci[_WH], ci[_WV]
    l0, vs, tmin = cf[_L0], cf[_VS], cf[_TMIN]
    h, v, X, gprev = x0[ci[_XH]], x0[ci[_XV]], cf[_X0], cf[_G0]
    start = int(cf[_FIRST])
    if want:
        D[:, :] = 0.0
        J[:, :] = 0.0
    for i in range(H):
        k = seq[i]
        _hop_inputs(i, seq, u, h, v, gprev, prob, x, p)
        shortfall = _clearance(kernels[2], i, seq, u, h, v, X, gprev, start, prob, w, want)
        start = k
        code = jac(x, p, d) if want else apex(x, p, d)
        if code != _OK:
            return code
        hn, vn, length, ascent = d[ci[_OH]], d[ci[_OV]], d[ci[_OL]], d[ci[_OTA]]
        foot = X + d[ci[_OF]]
        nxt = stones[seq[i + 1], _HEIGHT] if i + 1 < H else stones[k, _NEXT]
        short = cf[_FLOOR] + nxt - stones[k, _HEIGHT] - hn
        lift = tmin - ascent
        q = PER_HOP * i
        r[q] = cf[_WFOOT] * (foot - stones[k, _CENTRE]) / stones[k, _HALF]
        r[q + 1] = cf[_WHEIGHT] * (hn - nominal[i, 0]) / l0
        r[q + 2] = cf[_WSPEED] * (vn - nominal[i, 1]) / vs
        r[q + 3] = cf[_WFLOOR] * short / l0 if short > 0.0 else 0.0
        r[q + 4] = cf[_WFLOOR] * lift / tmin if lift > 0.0 else 0.0
        short_by = shortfall + CLEARANCE * l0  # the clearance kept, or the shortfall
        r[q + 5] = cf[_WFLOOR] * short_by / (CLEARANCE * l0) if short_by > 0.0 else 0.0
        hops[i, 0], hops[i, 1], hops[i, 2], hops[i, 3], hops[i, 4] = foot, hn, vn, X + length, ascent
        hops[i, 5] = shortfall
        if want:
            # d(output)/d(u): d/d(apex height) D_h + d/d(apex speed) D_v (+ D_x for the foot and
            # the next apex's x), plus this hop's own controls' columns
            for e in range(5):
                o = outs[e]
                carry = 1.0 if e == 0 or e == 3 else 0.0
                for b in range(n):
                    E[e, b] = _d(d, ci, o, wh) * D[0, b] + _d(d, ci, o, wv) * D[1, b] + carry * D[2, b]
                for c in range(nc):
                    E[e, i * nc + c] += _d(d, ci, o, ctl_i[2, c])
            for b in range(n):
                J[q, b] = cf[_WFOOT] * E[0, b] / stones[k, _HALF]
                J[q + 1, b] = cf[_WHEIGHT] * E[1, b] / l0
                J[q + 2, b] = cf[_WSPEED] * E[2, b] / vs
                J[q + 3, b] = -cf[_WFLOOR] * E[1, b] / l0 if short > 0.0 else 0.0
                J[q + 4, b] = -cf[_WFLOOR] * E[4, b] / tmin if lift > 0.0 else 0.0
                if short_by > 0.0:  # the foot's x at the stone's height: C (d/dh, d/dv, d/d angle)
                    dfoot = C[0] * D[0, b] + C[1] * D[1, b] + D[2, b] + (C[2] if b == i * nc + C[3] else 0.0)
                    J[q + 5, b] = -cf[_WFLOOR] * dfoot / (CLEARANCE * l0)
                else:
                    J[q + 5, b] = 0.0
                D[0, b], D[1, b], D[2, b] = E[1, b], E[2, b], E[3, b]
        h, v, X, gprev = hn, vn, X + length, stones[k, _HEIGHT]
    m0 = PER_HOP * H
    for b in range(n):
        c = b % nc
        r[m0 + b] = cf[_WREG] * (u[b] - ctl_f[2, c]) / ctl_f[3, c]
        if want:
            J[m0 + b, b] = cf[_WREG] / ctl_f[3, c]
    return _OK


@njit(error_model="numpy")
def _cholesky_solve(A, b, n, idx):
    """Solve A y = b over the ``n`` unknowns ``idx`` (A symmetric positive definite, its lower
    triangle overwritten by its Cholesky factor; y into b at idx); False when A is not positive
    definite."""
    for a in range(n):
        ia = idx[a]
        s = A[ia, ia]
        for k in range(a):
            s -= A[ia, idx[k]] ** 2
        if not s > 0.0:
            return False
        A[ia, ia] = math.sqrt(s)
        for c in range(a + 1, n):
            ic = idx[c]
            t = A[ic, ia]
            for k in range(a):
                t -= A[ic, idx[k]] * A[ia, idx[k]]
            A[ic, ia] = t / A[ia, ia]
    for a in range(n):
        ia = idx[a]
        t = b[ia]
        for k in range(a):
            t -= A[ia, idx[k]] * b[idx[k]]
        b[ia] = t / A[ia, ia]
    for a in range(n - 1, -1, -1):
        ia = idx[a]
        t = b[ia]
        for k in range(a + 1, n):
            t -= A[idx[k], ia] * b[idx[k]]
        b[ia] = t / A[ia, ia]
    return True


@njit(error_model="numpy")
def _least_angle(x, ci, cf, th):
    """``th``, or where the leg (q_r_td) cannot reach the ground from the row's apex at it, the
    least angle of its sign that can, and :data:`AIM_CLEARANCE` more: acos((h - ground) / q_r_td),
    the touchdown condition (report section 2.1; the deadbeat's ``touchdown_limit``)."""
    ratio = (x[ci[_XH]] - x[ci[_XG]]) / cf[_QR]
    if ratio >= 1.0:
        return th
    least = math.acos(max(ratio, -1.0)) + AIM_CLEARANCE
    if abs(th) >= least:
        return th
    return least if th >= 0.0 else -least


@njit(error_model="numpy")
def _aim(kernels, seq, u, cold, upto, prob, w):
    """The starting controls: the hops ``cold`` to ``upto`` - 1 get the angle that puts the foot in
    its stone, at the point of the usable part's inner half nearest where the hop's starting angle
    puts it (the least change of the gait), and, with a stiffness that changes the energy
    (``ci["ce"]``: k_d, or k_c), the stiffness that gives the next apex the nominal target's energy
    g_f H + V^2/2 (Newton's method on the map's outputs and their derivatives, at most
    :data:`AIM_STEPS` steps, within the bounds; the foot does not depend on the stiffness, so the
    two steps decouple); the other hops keep theirs. Returns the number of map evaluations
    (negative: the map failed at the start, the status's negative)."""
    apex, jac = kernels[0], kernels[1]
    stones, nominal, x0, _, ci, ctl_i, ctl_f, cf = prob
    x, p, d = w[0], w[1], w[2]
    H = seq.shape[0]
    nc = ci[_NC]
    of, oh, ov, xth = ci[_OF], ci[_OH], ci[_OV], ci[_XTH]
    ce = ci[_CE]
    ca = 0
    for c in range(nc):
        if ctl_i[0, c] == 0 and ctl_i[1, c] == xth:
            ca = c
    h, v, X, gprev = x0[ci[_XH]], x0[ci[_XV]], cf[_X0], cf[_G0]
    count = 0
    for i in range(H):
        k = seq[i]
        _hop_inputs(i, seq, u, h, v, gprev, prob, x, p)
        aimed = cold <= i < upto
        ran = False
        good_th, good_k = x[xth], _take(x, p, ctl_i, ce) if ce >= 0 else 0.0
        if aimed:
            x[xth] = min(max(_least_angle(x, ci, cf, x[xth]), ctl_f[0, ca]), ctl_f[1, ca])
            good_th = x[xth]
            energy = cf[_GF] * nominal[i, 0] + 0.5 * nominal[i, 1] ** 2
            spot = stones[k, _CENTRE]
            inner = 0.5 * stones[k, _HALF]
            for _ in range(AIM_STEPS):
                count += 1
                if jac(x, p, d) != _OK:
                    if not ran:
                        break
                    x[xth] = 0.5 * (x[xth] + good_th)  # back toward the controls that ran
                    if ce >= 0:
                        _put(x, p, ctl_i, ce, 0.5 * (_take(x, p, ctl_i, ce) + good_k))
                    continue
                if not ran:  # the first point: its foot, moved into the usable part's inner half
                    spot = min(max(X + d[of], stones[k, _CENTRE] - inner), stones[k, _CENTRE] + inner)
                ran = True
                good_th = x[xth]
                miss = X + d[of] - spot
                slope = _d(d, ci, of, ctl_i[2, ca])
                done = abs(miss) < 1e-4
                dth = -miss / slope if slope != 0.0 and not done else 0.0
                th = min(max(good_th + dth, ctl_f[0, ca]), ctl_f[1, ca])
                if ce >= 0:
                    good_k = _take(x, p, ctl_i, ce)
                    e_miss = cf[_GF] * d[oh] + 0.5 * d[ov] ** 2 - energy
                    de_th = cf[_GF] * _d(d, ci, oh, ctl_i[2, ca]) + d[ov] * _d(d, ci, ov, ctl_i[2, ca])
                    de_k = cf[_GF] * _d(d, ci, oh, ctl_i[2, ce]) + d[ov] * _d(d, ci, ov, ctl_i[2, ce])
                    done = done and abs(e_miss) < 1e-3 * energy
                    if de_k != 0.0 and not done:
                        kk = good_k - (e_miss + de_th * (th - good_th)) / de_k
                        _put(x, p, ctl_i, ce, min(max(kk, ctl_f[0, ce]), ctl_f[1, ce]))
                if done:
                    break
                x[xth] = th
            for c in range(nc):
                u[i * nc + c] = _take(x, p, ctl_i, c)
        count += 1
        code = apex(x, p, d)
        if code != _OK and aimed and ran:  # the last Newton step failed: the last point that ran
            x[xth] = good_th
            if ce >= 0:
                _put(x, p, ctl_i, ce, good_k)
            for c in range(nc):
                u[i * nc + c] = _take(x, p, ctl_i, c)
            count += 1
            code = apex(x, p, d)
        if code != _OK:
            return -code
        h, v, X, gprev = d[oh], d[ov], X + d[ci[_OL]], stones[k, _HEIGHT]
    return count


@njit(error_model="numpy")
def _start(kernels, seq, u, cold, prob, w):
    """The starting controls of a sequence (module docstring): ``u`` (the given ones) aimed from hop
    ``cold`` on; else aimed on that hop alone (a hop that cannot reach its stone from where the aimed
    ones leave it); then the same from the nominal controls (a warm start that no longer fits).
    Returns the map evaluations, or the negative status of the map's failure."""
    ci, ctl_f = prob[4], prob[6]
    keep = w[16]
    H = seq.shape[0]
    nc = ci[_NC]
    n = H * nc
    for b in range(n):
        u[b] = min(max(u[b], ctl_f[0, b % nc]), ctl_f[1, b % nc])
        keep[b] = u[b]
    evaluations = 0
    for attempt in range(4):
        if attempt == 2 and cold == 0:
            break
        for b in range(n):
            u[b] = keep[b] if attempt < 2 else ctl_f[2, b % nc]
        first = cold if attempt < 2 else 0
        upto = H if attempt % 2 == 0 else first + 1
        got = _aim(kernels, seq, u, first, upto, prob, w)
        if got >= 0:
            return evaluations + got
        evaluations = got
    return evaluations


@njit(error_model="numpy")
def _cost(r):
    c = 0.0
    for a in range(r.shape[0]):
        c += r[a] * r[a]
    return c


@njit(error_model="numpy")
def _lm(kernels, seq, u, iters, prob, w, out):
    """Levenberg-Marquardt on one sequence from the controls ``u`` (updated), at most ``iters``
    steps (module docstring); its row ``out`` gets the status, cost, counts and the hops."""
    stones, ci, ctl_f, cf = prob[0], prob[4], prob[6], prob[7]
    r, J, rt, Jt, A, g, delta, ut, hops, hopt, free = w[5:16]
    H = seq.shape[0]
    nc = ci[_NC]
    n = H * nc
    m = r.shape[0]
    lo, hi, scale = ctl_f[0], ctl_f[1], ctl_f[4]
    out[_EVAL] += 1.0
    code = _chain(kernels, True, u, seq, prob, w, r, J, hops)
    out[_STATUS] = float(code)
    if code != _OK:
        return
    cost = _cost(r)
    mu = -1.0
    nu = 2.0
    converged = False
    done = 0
    while done < iters and not converged:
        done += 1
        # the scaled gradient J_s^T r and the free controls
        nf = 0
        for b in range(n):
            s = 0.0
            for a in range(m):
                s += J[a, b] * r[a]
            g[b] = s * scale[b % nc]
            held = (u[b] <= lo[b % nc] and g[b] > 0.0) or (u[b] >= hi[b % nc] and g[b] < 0.0)
            if not held:
                free[nf] = b
                nf += 1
        if nf == 0:
            converged = True
            break
        diag_max = 0.0
        for a in range(nf):
            ia = free[a]
            for c in range(a + 1):
                ic = free[c]
                s = 0.0
                for q in range(m):
                    s += J[q, ia] * J[q, ic]
                A[ia, ic] = s * scale[ia % nc] * scale[ic % nc]
            diag_max = max(diag_max, A[ia, ia])
        if mu < 0.0:
            mu = 1e-3 * diag_max
        for a in range(nf):
            ia = free[a]
            A[ia, ia] += mu * max(A[ia, ia], 1e-12 * diag_max + 1e-300)
            delta[ia] = -g[ia]
        ok = _cholesky_solve(A, delta, nf, free)
        step = 0.0
        ut[:] = u
        if ok:
            for a in range(nf):
                b = free[a]
                ut[b] = min(max(u[b] + delta[b] * scale[b % nc], lo[b % nc]), hi[b % nc])
                step = max(step, abs(ut[b] - u[b]) / scale[b % nc])
        cost_t = math.inf
        if ok:
            out[_EVAL] += 1.0
            if _chain(kernels, True, ut, seq, prob, w, rt, Jt, hopt) == _OK:
                cost_t = _cost(rt)
        if cost_t < cost:
            # the decrease the linear model promised, for Nielsen's update of mu:
            # |r + J du|^2 = cost + 2 (J^T r) du + |J du|^2 (g is J^T r scaled)
            pred = 0.0
            for b in range(n):
                pred -= 2.0 * g[b] / scale[b % nc] * (ut[b] - u[b])
            for a in range(m):
                s = 0.0
                for b in range(n):
                    s += J[a, b] * (ut[b] - u[b])
                pred -= s * s
            drop = cost - cost_t
            u[:] = ut
            r[:] = rt
            J[:, :] = Jt
            hops[:, :] = hopt
            rho = drop / pred if pred > 0.0 else 1.0
            mu *= max(1.0 / 3.0, 1.0 - (2.0 * min(rho, 1.0) - 1.0) ** 3)
            nu = 2.0
            cost = cost_t
            converged = step < 1e-7 or drop <= cf[_TOL] * cost
        elif ok and step < 1e-12:  # the projected step does not move: a minimum on the bounds
            converged = True
        else:
            mu *= nu
            nu *= 2.0
            converged = mu > 1e12 * max(diag_max, 1e-300)
    out[_COST] = cost
    out[_ITER] += float(done)
    out[_CONV] = 1.0 if converged else 0.0
    for i in range(H):
        k = seq[i]
        base = _NH + i * _NHOP
        out[base + _FOOT] = hops[i, 0]
        out[base + _MARGIN] = min(hops[i, 0] - stones[k, _LO], stones[k, _HI] - hops[i, 0])
        out[base + _APH] = hops[i, 1]
        out[base + _APV] = hops[i, 2]
        out[base + _APX] = hops[i, 3]
        out[base + _TA] = hops[i, 4]
        out[base + _CLEAR] = hops[i, 5]
    base = _NH + H * _NHOP
    for b in range(n):
        out[base + b] = u[b]


@njit(error_model="numpy")
def _neutral_foot(apex, U_nom, prob, w):
    """The neutral foothold, the enumeration's aim: the foot's x at the first hop's nominal controls
    on the ground under the apex (at the least angle that reaches the ground where that one does
    not; the leg's reach, q_r_td sin of the angle, where the map fails there too)."""
    ci, ctl_i, cf = prob[4], prob[5], prob[7]
    x, p, d = w[0], w[1], w[2]
    x0, p0 = prob[2], prob[3]
    x[:] = x0
    p[:] = p0
    x[ci[_XG]] = 0.0
    for c in range(ci[_NC]):
        _put(x, p, ctl_i, c, U_nom[0, c])
    x[ci[_XTH]] = _least_angle(x, ci, cf, x[ci[_XTH]])
    if apex(x, p, d) == _OK:
        return cf[_X0] + d[ci[_OF]]
    return cf[_X0] + cf[_QR] * math.sin(x[ci[_XTH]])


@njit(error_model="numpy")
def _enumerate(stones, first, last, H, cf, SEQ):
    """The candidate sequences (module docstring, 1) into the rows of ``SEQ``; returns their count
    (at most its rows)."""
    aim, reach, step = cf[_AIMX], cf[_REACH], cf[_STEP]
    idx = np.empty(H, dtype=np.int64)
    count = 0
    level = 0
    idx[0] = first - 1
    while level >= 0 and count < SEQ.shape[0]:
        idx[level] += 1
        k = idx[level]
        if k >= last:
            level -= 1
            continue
        lo, hi = stones[k, _LO], stones[k, _HI]
        if level == 0:
            fits = hi >= aim - reach and lo <= aim + reach
        else:
            j = idx[level - 1]
            near = 0.0 if k == j else lo - stones[j, _HI]
            far = hi - stones[j, _LO]
            fits = far >= step - reach and near <= step + reach
        if not fits:
            continue
        if level == H - 1:
            SEQ[count, :] = idx
            count += 1
        else:
            level += 1
            idx[level] = k - 1  # the next hop from this stone on (a long stone takes two feet)
    return count


@njit(error_model="numpy")
def _work(nx, np_, width, H, nc, ci):
    """The work arrays of a plan (the comment above :func:`_put`)."""
    n = H * nc
    m = PER_HOP * H + n
    return (
        np.empty(nx),
        np.empty(np_),
        np.empty(width),
        np.zeros((3, n)),
        np.zeros((5, n)),
        np.empty(m),
        np.zeros((m, n)),
        np.empty(m),
        np.zeros((m, n)),
        np.zeros((n, n)),
        np.empty(n),
        np.empty(n),
        np.empty(n),
        np.empty((H, 6)),
        np.empty((H, 6)),
        np.empty(n, dtype=np.int64),
        np.empty(n),
        np.zeros(4),
        np.empty(ci[_DNX]),
        np.empty(ci[_DWIDTH]),
    )


_I1, _F1 = types.int64[::1], types.float64[::1]
_I2, _F2 = types.int64[:, ::1], types.float64[:, ::1]


@njit(
    types.void(MODEL, MODEL, MODEL, _F2, _I1, _F2, _F1, _F1, _F1, _I1, _I2, _F2, _F1, _F2, _I2, _F2, _I1),
    cache=True,
    error_model="numpy",
    nogil=True,
)
def plan_rows(
    apex, jac, descent, stones, span, U_nom, warm_u, x0, p0, ci, ctl_i, ctl_f, cf, nominal, SEQ, OUT, RES
):
    """One plan (module docstring) into ``SEQ`` (the candidate sequences), ``OUT`` (a row each) and
    ``RES`` (:data:`RESULTS`). ``span``: the stones seen (first, last), the Jacobian kernel's row
    length, then the previous plan's stones after its first hop (H - 1 of them; -1: no previous
    plan), whose controls ``warm_u`` start the sequences that continue it; ``U_nom`` (H, nc): each
    hop's nominal controls; ``nominal`` (H, 2): each hop's target height and speed."""
    H = SEQ.shape[1]
    nc = ci[_NC]
    n = H * nc
    prob = (stones, nominal, x0, p0, ci, ctl_i, ctl_f, cf)
    kernels = (apex, jac, descent)
    cf[_FIRST] = float(span[0])
    w = _work(x0.shape[0], p0.shape[0], span[2], H, nc, ci)
    cf[_AIMX] = _neutral_foot(apex, U_nom, prob, w)
    count = _enumerate(stones, span[0], span[1], H, cf, SEQ)
    RES[0], RES[1], RES[2] = count, -1, 3
    if count == 0:
        return
    u = np.empty(n)
    U = np.empty((count, n))
    best_cost = math.inf
    for s in range(count):
        row = OUT[s]
        row[:] = math.nan
        row[_ITER], row[_EVAL] = 0.0, 0.0
        # the start: the previous plan's controls where this sequence continues it
        cold = 0
        if H > 1 and span[3] >= 0:
            cold = H - 1
            for i in range(H - 1):
                if SEQ[s, i] != span[3 + i]:
                    cold = 0
        for i in range(H):
            for c in range(nc):
                u[i * nc + c] = warm_u[i * nc + c] if i < cold else U_nom[i, c]
        got = _start(kernels, SEQ[s], u, cold, prob, w)
        if got < 0:
            row[_STATUS] = float(-got)
            continue
        row[_EVAL] = float(got)
        _lm(kernels, SEQ[s], u, SCREEN, prob, w, row)
        U[s, :] = u
        if row[_STATUS] == _OK:
            best_cost = min(best_cost, row[_COST])
    # the second phase: the sequences near the best go on to convergence
    for s in range(count):
        row = OUT[s]
        if row[_STATUS] != _OK or row[_CONV] != 0.0 or row[_COST] > best_cost + SCREEN_GAP:
            continue
        u[:] = U[s]
        _lm(kernels, SEQ[s], u, ci[_MAXIT] - SCREEN, prob, w, row)
    # the choice: the least cost among the feasible sequences, else among those that ran
    best, best_ran = -1, -1
    for s in range(count):
        row = OUT[s]
        if row[_STATUS] != _OK:
            continue
        feasible = True
        for i in range(H):
            base = _NH + i * _NHOP
            viable = row[base + _APV] * nominal[i, 1] >= 0.0 and row[base + _TA] >= 0.5 * cf[_TMIN]
            if not (row[base + _MARGIN] >= 0.0 and row[base + _CLEAR] <= 0.0 and viable):
                feasible = False
        row[_FEAS] = 1.0 if feasible else 0.0
        if best_ran < 0 or row[_COST] < OUT[best_ran, _COST]:
            best_ran = s
        if feasible and (best < 0 or row[_COST] < OUT[best, _COST]):
            best = s
    if best >= 0:
        RES[1], RES[2] = best, 0
    elif best_ran >= 0:
        RES[1], RES[2] = best_ran, 1
    else:
        RES[2] = 2


_BOUND: dict = {}


def bind(apex, jac, descent):
    """:func:`plan_rows` bound to one map's kernels (``apex``, ``jac``: its apex-return role
    kernels; ``descent``: the model's ``apex_to_touchdown``), compiled once per map and process
    (numba types the kernels as constants), as :func:`.compiled.bind` binds the deadbeat's."""
    hit = _BOUND.get((apex, jac))
    if hit is not None:
        return hit

    @njit(error_model="numpy", nogil=True)
    def rows(stones, span, U_nom, warm_u, x0, p0, ci, ctl_i, ctl_f, cf, nominal, SEQ, OUT, RES):
        plan_rows(
            apex,
            jac,
            descent,
            stones,
            span,
            U_nom,
            warm_u,
            x0,
            p0,
            ci,
            ctl_i,
            ctl_f,
            cf,
            nominal,
            SEQ,
            OUT,
            RES,
        )

    _BOUND[(apex, jac)] = rows
    return rows
