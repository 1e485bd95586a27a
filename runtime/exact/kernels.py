"""The exact simulator's scalar kernels, in the generated kernels' calling convention.

``derive/maps/exact.py`` declares the map ``"exact"`` like every other map; its stance is not
derived symbolically but integrated numerically, so its declaration names these hand-written
kernels as *external* ones (``derive/ir.py``: ``Kernel.external``). The generated module
``generated/exact.py`` calls them from its stance, state-at-time and apex-return kernels (the
flights, the ground, the signed speed and the step geometry are the same generated composition as
every map's), and the generated Jacobians differentiate through :func:`stance_jacobian`.

The convention (checked at generation against the declaration): njit scalar functions of floats,
arguments in the order the declaration gives, never raising; they return a tuple of the declared
outputs followed by the status (all outputs NaN unless the status is OK). The stance time limit is
:func:`.reference.stance_time_limit` of the parameters.

- :func:`stance`: touchdown state -> t_bottom, t_stance, the bottom and the liftoff states
  (the index's stance outputs, in their order), status.
- :func:`stance_jacobian`: the same outputs, then d output_i / d input_j row-major over the inputs
  (q_r_td, q_rd_td, q_th_td, q_thd_td, k_c, k_d), status (variational equations,
  :mod:`.jacobian`).
- :func:`compression`: touchdown state -> t_half (the bottom's time), the bottom state (q_rd = 0
  exactly), status: the stance's touchdown checks and compression-phase failures; a bottom at or
  beyond q_r_lo is the decompression's NO_LIFTOFF, not the compression's failure.
- :func:`decompression`: bottom state -> t_half (from the bottom), the liftoff state, status: the
  stance's bottom checks (NO_LIFTOFF when q_r_b >= q_r_lo, RECOMPRESSION when the k_d spring cannot
  start extending the leg) and decompression-phase failures; q_rd_b is not read (0 at the bottom;
  a non-finite one is INVALID_INPUT all the same).
- :func:`state_at`: time t after touchdown and the touchdown state -> the polar state at t, status.

Every kernel runs the one hybrid stance of :func:`.compiled.hybrid_stance` (the same steps, events
and checks): compression then decompression gives :func:`stance`'s bottom, liftoff and times to
round-off (t_stance = t_bottom + the decompression's t_half; the compression is the stance's own
integration, bitwise; the liftoff state within 2.5e-14 and t_stance within 2.2e-15 s over 2910
random stances, tests/test_exact_compiled.py). Each half's time limit is
:func:`.reference.stance_time_limit` with its own stiffness for both springs. INVALID_INPUT
(nothing integrated) for a non-finite argument, a state outside its domain (q_r outside (0, l0],
|q_th| >= pi/2), parameters outside SlipParams' domain or non-positive tolerances.

Each is inlined into the generated kernel that calls it (:data:`.compiled.INLINE`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from . import compiled as ec
from . import jacobian as ej
from .reference import stance_time_limit

__all__ = ["STANCE_JACOBIAN_WRT", "compression", "decompression", "stance", "stance_jacobian", "state_at"]

#: The inputs :func:`stance_jacobian` differentiates with respect to, in its column order.
STANCE_JACOBIAN_WRT = ej.INPUTS

# numba builds fixed-length tuples only: the literal tuples below are 10 outputs and 10 x 6 entries.
if ec.N_STANCE != 10 or (ej.N_OUT, ej.N_IN) != (10, 6):
    raise RuntimeError(
        f"the exact kernels' tuples need updating: {ec.N_STANCE} outputs, {ej.N_OUT} x {ej.N_IN}"
    )


@njit(**ec.INLINE)
def stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """The exact stance from a polar touchdown state (:func:`.compiled.stance_into`)."""
    out = np.empty(ec.N_STANCE)
    t_max = stance_time_limit(m, l0, k_c, k_d, g_s)
    code = ec.stance_into(
        q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out
    )
    return (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], code)


@njit(**ec.INLINE)
def stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """The exact stance and its Jacobian with respect to :data:`STANCE_JACOBIAN_WRT`
    (:func:`.jacobian.jacobian_into`): the outputs of :func:`stance`, then the Jacobian row-major."""
    out = np.empty(ej.N_OUT)
    jac = np.empty((ej.N_OUT, ej.N_IN))
    t_max = stance_time_limit(m, l0, k_c, k_d, g_s)
    code = ej.jacobian_into(
        q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out, jac
    )
    j = jac.ravel()
    return (
        out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9],
        j[0], j[1], j[2], j[3], j[4], j[5], j[6], j[7], j[8], j[9],
        j[10], j[11], j[12], j[13], j[14], j[15], j[16], j[17], j[18], j[19],
        j[20], j[21], j[22], j[23], j[24], j[25], j[26], j[27], j[28], j[29],
        j[30], j[31], j[32], j[33], j[34], j[35], j[36], j[37], j[38], j[39],
        j[40], j[41], j[42], j[43], j[44], j[45], j[46], j[47], j[48], j[49],
        j[50], j[51], j[52], j[53], j[54], j[55], j[56], j[57], j[58], j[59],
        code,
    )  # fmt: skip


@njit(**ec.INLINE)
def compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, rtol, atol):
    """The compression half, touchdown -> bottom with k_c (:func:`.compiled.half_into`):
    (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, status), t_half the time of the bottom."""
    out = np.empty(5)
    t_max = stance_time_limit(m, l0, k_c, k_c, g_s)
    code = ec.half_into(
        q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, rtol, atol, t_max, True, out
    )
    return (out[0], out[1], out[2], out[3], out[4], code)


@njit(**ec.INLINE)
def decompression(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, rtol, atol):
    """The decompression half, bottom -> liftoff with k_d (:func:`.compiled.half_into`; q_rd_b is
    not read, 0 at the bottom): (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, status), t_half
    from the bottom."""
    out = np.empty(5)
    t_max = stance_time_limit(m, l0, k_d, k_d, g_s)
    code = ec.half_into(
        q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, rtol, atol, t_max, False, out
    )
    return (out[0], out[1], out[2], out[3], out[4], code)


@njit(**ec.INLINE)
def state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """The polar state a time t after touchdown (:func:`.compiled.state_at_into`):
    (q_r, q_rd, q_th, q_thd, status).

    The exact stance's state at t: compression with k_c until the bottom, then k_d; t from 0 to the
    stance time limit (else INVALID_INPUT). For t beyond liftoff, the stance equations with k_d
    continued past liftoff (no liftoff, recompression or fall event), as the approximate maps'
    closed forms are: not a flight. The status is the stance's (a stance that fails has no state
    at any t)."""
    out = np.empty(4)
    t_max = stance_time_limit(m, l0, k_c, k_d, g_s)
    code = ec.state_at_into(
        t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out
    )
    return (out[0], out[1], out[2], out[3], code)
