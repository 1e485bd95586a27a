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
- :func:`state_at`: the polar state a time t after touchdown (k_c until the bottom, then k_d), status;
  after liftoff the stance equations continued, as the approximate maps' closed forms are.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import compiled as ec
from . import dop853
from . import jacobian as ej
from .reference import COLLAPSE_FRACTION, max_step, stance_time_limit

__all__ = ["STANCE_JACOBIAN_WRT", "stance", "stance_jacobian", "state_at"]

#: The inputs :func:`stance_jacobian` differentiates with respect to, in its column order.
STANCE_JACOBIAN_WRT = ej.INPUTS

_JIT = {"cache": True, "error_model": "numpy"}

# numba builds fixed-length tuples only: the literal tuples below are 10 outputs and 10 x 6 entries.
if ec.N_STANCE != 10 or (ej.N_OUT, ej.N_IN) != (10, 6):
    raise RuntimeError(
        f"the exact kernels' tuples need updating: {ec.N_STANCE} outputs, {ej.N_OUT} x {ej.N_IN}"
    )


@njit(**_JIT)
def stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """The exact stance from a polar touchdown state (:func:`.compiled.stance_into`)."""
    out = np.empty(ec.N_STANCE)
    t_max = stance_time_limit(m, l0, k_c, k_d, g_s)
    code = ec.stance_into(
        q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out
    )
    return (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], code)


@njit(**_JIT)
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


#: state_at watches the bottom while compressing (then switches to k_d), and only the failures after.
_TO_BOTTOM = np.array([math.nan, +1.0, -1.0, -1.0])
_AFTER_BOTTOM = np.array([math.nan, math.nan, -1.0, -1.0])


@njit(**_JIT)
def state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """The polar state ``t`` >= 0 after touchdown: compression with k_c until the bottom (q_rd up
    through 0), then k_d; no liftoff event (past liftoff the stance equations continue)."""
    nan = math.nan
    if not (math.isfinite(t) and t >= 0.0 and ec.valid_polar(q_r_td, q_rd_td, q_th_td, q_thd_td, l0)):
        return (nan, nan, nan, nan, ec.INVALID_INPUT)
    r_min = COLLAPSE_FRACTION * l0
    pe = (q_r_lo, r_min)
    y0 = np.array((q_r_td, q_rd_td, q_th_td, q_thd_td))
    y = np.empty(4)
    code, t_end, event, _ = dop853.solve(
        ec.POLAR_FIELD(), (m, l0, k_c, g_s), ec.STANCE_EVENTS(), pe, _TO_BOTTOM, 0.0, y0, t,
        rtol, atol, max_step(m, l0, k_c, g_s), ec.N_POLAR, y,
    )  # fmt: skip
    if code == dop853.EVENT and event == ec.EV_RADIAL and t_end < t:
        y[ec.Q_RD] = 0.0
        y_b = y.copy()
        code, t_end, event, _ = dop853.solve(
            ec.POLAR_FIELD(), (m, l0, k_d, g_s), ec.STANCE_EVENTS(), pe, _AFTER_BOTTOM, t_end, y_b, t,
            rtol, atol, max_step(m, l0, k_d, g_s), ec.N_POLAR, y,
        )  # fmt: skip
    if code == dop853.FAILED:
        return (nan, nan, nan, nan, ec.INTEGRATION_FAILED)
    if code == dop853.EVENT and event != ec.EV_RADIAL:
        return (nan, nan, nan, nan, ec.FALL)
    return (y[0], y[1], y[2], y[3], ec.OK)
