"""Exact derivatives of the exact stance: variational equations with saltation matrices.

The stance of :mod:`.compiled` maps the inputs ``w = (q_r_td, q_rd_td, q_th_td, q_thd_td,
k_c, k_d)`` (:data:`INPUTS`) to its outputs (:data:`OUTPUTS`, the stance columns of the index:
``t_bottom``, ``t_stance``, the bottom and the liftoff states). This module integrates, with the
same compiled DOP853 (:mod:`.dop853`), the polar state y together with its sensitivity
S = dy(t)/dw (4 x 6) at fixed time t:

* dS/dt = J(y, k) S + df/dk e_k^T, column by column the generated kernel
  ``slip_model.stance_polar_tangent`` (derived from the equations of motion (2)-(3)), k = k_c and
  e_k the k_c column while compressing, k = k_d and the k_d column after the bottom; S = [I | 0 | 0]
  at touchdown;
* the steps, the events and y are exactly those of :func:`.compiled.stance_into`: both run the
  one hybrid stance :func:`.compiled.hybrid_stance`, here with the augmented field (only y
  controls the step size) and :func:`bottom_saltation` as its bottom step, so S is the derivative
  of the discrete flow at those steps and the values returned here equal
  ``slipmaps.stance("exact", ...)``'s;
* bottom, g = q_rd = 0 with the switch f_c -> f_d (k_c -> k_d): dt_b/dw = -(dg/dy) S / (dg/dy . f_c),
  d(bottom)/dw = S + f_c dt_b/dw (the bottom state moves on the surface q_rd = 0), and the
  variation continues at fixed time through the saltation matrix
  S+ = (I + (f_d - f_c) (dg/dy)^T / (dg/dy . f_c)) S-;
* liftoff, g = q_r - q_r_lo = 0: dt_lo/dw = -(dg/dy) S / (dg/dy . f_d) and
  d(liftoff)/dw = (I - f_d (dg/dy)^T / (dg/dy . f_d)) S (the map to the event surface).

Derivatives are in SI units per unit input (per N/m for k_c, k_d). Kernels never raise: NaN and a
status (those of the stance) unless OK. Measured against central differences of the compiled
simulator (tests/test_exact_jacobian.py: human runner and robot hopper, symmetric and nonsymmetric
touchdowns, k_c == k_d and k_c != k_d; step 1e-5 times each input's scale): every column agrees to
at most 1.0e-9 of its largest entry.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from slipmaps.generated import maps_index
from slipmaps.generated.slip_model import stance_polar_tangent

from . import compiled as ec
from . import dop853

__all__ = ["INPUTS", "OUTPUTS", "jacobian_into"]

#: The rows of the Jacobian: the stance outputs of the index.
OUTPUTS = ec.STANCE_NAMES
#: Its columns: the touchdown state (the index's names), then the two stiffnesses.
INPUTS = (*maps_index.TOUCHDOWN, "k_c", "k_d")
N_OUT, N_IN = len(OUTPUTS), len(INPUTS)
K_C, K_D = INPUTS.index("k_c"), INPUTS.index("k_d")
TOUCHDOWN = tuple(INPUTS.index(n) for n in maps_index.TOUCHDOWN)
#: The augmented state: the polar state, then S row by row (S[i, j] at N_POLAR + N_IN i + j).
N_POLAR = ec.N_POLAR
N_AUG = N_POLAR + N_POLAR * N_IN
Q_R, Q_RD, Q_TH, Q_THD = ec.Q_R, ec.Q_RD, ec.Q_TH, ec.Q_THD
T_BOTTOM, T_STANCE, BOTTOM, LIFTOFF = ec.T_BOTTOM, ec.T_STANCE, ec.BOTTOM, ec.LIFTOFF
OK = ec.OK
if (Q_R, Q_RD, Q_TH, Q_THD) != tuple(range(N_POLAR)):
    raise RuntimeError("the integrated state must be in the polar order (q_r, q_rd, q_th, q_thd)")
#: Where each state component's row of S starts in the augmented state.
_S_Q_R, _S_Q_RD, _S_Q_TH, _S_Q_THD = (N_POLAR + N_IN * i for i in (Q_R, Q_RD, Q_TH, Q_THD))

_JIT = {"cache": True, "error_model": "numpy"}


@njit(**_JIT)
def augmented_field(t, z, p, dz):
    """d/dt (y, S): the stance field and its variational equations, S column by column
    (``slip_model.stance_polar_tangent``); p = (m, l0, k, g_s, column of k)."""
    m, l0, k, g_s, k_column = p
    ec.polar_field(t, z, (m, l0, k, g_s), dz)
    q_r, q_rd, q_th, q_thd = z[Q_R], z[Q_RD], z[Q_TH], z[Q_THD]
    col = int(k_column)
    for j in range(N_IN):
        d = stance_polar_tangent(
            q_r,
            q_rd,
            q_th,
            q_thd,
            z[_S_Q_R + j],
            z[_S_Q_RD + j],
            z[_S_Q_TH + j],
            z[_S_Q_THD + j],
            1.0 if j == col else 0.0,
            m,
            l0,
            k,
            g_s,
        )
        dz[_S_Q_R + j] = d[Q_R]
        dz[_S_Q_RD + j] = d[Q_RD]
        dz[_S_Q_TH + j] = d[Q_TH]
        dz[_S_Q_THD + j] = d[Q_THD]


AUGMENTED_FIELD = dop853.static(augmented_field)


@njit(**_JIT)
def _event_time_gradient(z, component, rate, dt):
    """dt_event/dw = -(dg/dy) S / (dg/dy . f) for g = y[component] - const (rate = dg/dt)."""
    for j in range(N_IN):
        dt[j] = -z[N_POLAR + N_IN * component + j] / rate


#: The bottom step's record: dt_bottom/dw (N_IN), then d(bottom)/dw row by row (N_POLAR x N_IN).
N_WORK = N_IN + N_POLAR * N_IN


@njit(**_JIT)
def bottom_saltation(z_b, m, l0, k_c, k_d, g_s, work):
    """The Jacobian's step at the bottom (g = q_rd = 0, the switch f_c -> f_d), called by the
    hybrid stance after its bottom checks: the event time's gradient into ``work[:N_IN]``, the
    bottom state's derivative on the surface q_rd = 0 into ``work[N_IN:]``, and S- -> S+ (the
    saltation matrix) in ``z_b``."""
    f_c = np.empty(N_POLAR)
    f_d = np.empty(N_POLAR)
    ec.polar_field(0.0, z_b, (m, l0, k_c, g_s), f_c)
    ec.polar_field(0.0, z_b, (m, l0, k_d, g_s), f_d)
    dt_b = work[:N_IN]
    _event_time_gradient(z_b, Q_RD, f_c[Q_RD], dt_b)
    for i in range(N_POLAR):
        for j in range(N_IN):
            s_ij = z_b[N_POLAR + N_IN * i + j]
            work[N_IN + N_IN * i + j] = s_ij + f_c[i] * dt_b[j]
            z_b[N_POLAR + N_IN * i + j] = s_ij - (f_d[i] - f_c[i]) * dt_b[j]


BOTTOM_SALTATION = dop853.static(bottom_saltation)


@njit(**ec.INLINE)
def jacobian_into(
    q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out, jac
):
    """The stance (the :data:`OUTPUTS` row into ``out``, as :func:`.compiled.stance_into`) and
    its Jacobian d(OUTPUTS)/d(INPUTS) into ``jac`` (N_OUT x N_IN); NaN unless OK; returns the status.

    The hybrid stance is :func:`.compiled.hybrid_stance` (its events, checks and statuses) on the
    augmented state, with :func:`bottom_saltation` at the bottom; the map to the liftoff surface
    is applied here."""
    for i in range(N_OUT):
        out[i] = math.nan
        for j in range(N_IN):
            jac[i, j] = math.nan
    z = np.zeros(N_AUG)
    z[Q_R] = q_r_td
    z[Q_RD] = q_rd_td
    z[Q_TH] = q_th_td
    z[Q_THD] = q_thd_td
    for i in range(N_POLAR):
        z[N_POLAR + N_IN * i + TOUCHDOWN[i]] = 1.0
    z_b = np.empty(N_AUG)
    z_lo = np.empty(N_AUG)
    work = np.empty(N_WORK)
    status, t_bottom, t_stance, _ = ec.hybrid_stance(
        AUGMENTED_FIELD(),
        (m, l0, k_c, g_s, float(K_C)),
        (m, l0, k_d, g_s, float(K_D)),
        BOTTOM_SALTATION(),
        work,
        z,
        True,
        True,
        m,
        l0,
        k_c,
        k_d,
        g_s,
        q_r_lo,
        rtol,
        atol,
        t_max,
        math.inf,  # no sample: the sample array (work) is never written by the integrator
        work,
        z_b,
        z_lo,
    )
    if status != OK:
        return status
    # Liftoff: event time and the map to the surface q_r = q_r_lo.
    f_lo = np.empty(N_POLAR)
    ec.polar_field(0.0, z_lo, (m, l0, k_d, g_s), f_lo)
    dt_lo = np.empty(N_IN)
    _event_time_gradient(z_lo, Q_R, f_lo[Q_R], dt_lo)
    out[T_BOTTOM] = t_bottom
    out[T_STANCE] = t_stance
    for i in range(N_POLAR):
        out[BOTTOM + i] = z_b[i]
        out[LIFTOFF + i] = z_lo[i]
    for j in range(N_IN):
        jac[T_BOTTOM, j] = work[j]
        jac[T_STANCE, j] = dt_lo[j]
        for i in range(N_POLAR):
            jac[BOTTOM + i, j] = work[N_IN + N_IN * i + j]
            jac[LIFTOFF + i, j] = z_lo[N_POLAR + N_IN * i + j] + f_lo[i] * dt_lo[j]
    return OK
