"""The yardstick: Geyer et al.'s stance map written by hand as one parallel numba kernel.

Same math as the generated ``geyer_stance`` (report eqs 7-14, 17, 19, with the touchdown energy
(8) taken with Assumption 2's Taylor polynomial), the same checks and status codes, the same
(n, 10) output columns. ``benchmarks/bench_maps.py`` times the public batch API against it and
checks that both agree. Not part of the package: it exists to measure the generated code.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange
from slipmaps.generated.status import Status

OK = int(Status.OK)
INVALID_INPUT = int(Status.INVALID_INPUT)
NOT_COMPRESSING = int(Status.TOUCHDOWN_NOT_COMPRESSING)
NO_REAL_SOLUTION = int(Status.NO_REAL_SOLUTION)
OUTSIDE = int(Status.TOUCHDOWN_OUTSIDE_OSCILLATION)
NO_LIFTOFF = int(Status.NO_LIFTOFF)
FALL = int(Status.FALL)
NUMERICAL_RANGE = int(Status.NUMERICAL_RANGE)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_stance_handwritten(td, m, l0, k, g_s, q_r_lo, out, status):
    """Rows of ``td`` (n, 4) touchdown states -> ``out`` (n, 10), ``status`` (n,)."""
    n = td.shape[0]
    w0sq = k / m
    g_l0 = g_s / l0
    inv_l0 = 1.0 / l0
    params_ok = (
        math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s)
        and math.isfinite(q_r_lo) and m > 0.0 and l0 > 0.0 and k > 0.0 and g_s > 0.0
        and 0.0 < q_r_lo <= l0
    )  # fmt: skip
    rho_lo = q_r_lo * inv_l0 - 1.0
    for i in prange(n):
        q_r, q_rd, q_th, q_thd = td[i, 0], td[i, 1], td[i, 2], td[i, 3]
        code = OK
        if not (
            params_ok and math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th)
            and math.isfinite(q_thd) and 0.0 < q_r <= l0 and abs(q_th) < 0.5 * math.pi
        ):  # fmt: skip
            code = INVALID_INPUT
        elif not q_rd < 0.0:
            code = NOT_COMPRESSING
        else:
            rho0 = q_r * inv_l0 - 1.0
            omega = q_r * q_r * q_thd * inv_l0 * inv_l0
            w2 = omega * omega
            # (8) at touchdown with the Taylor polynomial of Assumption 2
            eps = (q_rd * inv_l0) ** 2 + w2 * (1.0 - 2.0 * rho0 + 3.0 * rho0 * rho0)
            eps += w0sq * rho0 * rho0 + 2.0 * g_l0 * (1.0 + rho0)
            wh2 = w0sq + 3.0 * w2
            inv_wh2 = 1.0 / wh2
            wh = math.sqrt(wh2)
            a = (w2 - g_l0) * inv_wh2
            b2 = a * a + (eps - w2 - 2.0 * g_l0) * inv_wh2
            if not b2 > 0.0:
                code = NO_REAL_SOLUTION
            else:
                b = math.sqrt(b2)
                s_td = (rho0 - a) / b
                s_lo = (rho_lo - a) / b
                if not 1.0 + a - b > 0.0:
                    code = FALL
                elif not abs(s_td) <= 1.0:
                    code = OUTSIDE
                elif not abs(s_lo) <= 1.0:
                    code = NO_LIFTOFF
                else:
                    # event phases (12)-(14); their cosines from the branches: no trig call
                    ph_td = math.pi - math.asin(s_td)
                    ph_b = 1.5 * math.pi
                    ph_lo = 2.0 * math.pi + math.asin(s_lo)
                    c_td = -math.sqrt(1.0 - s_td * s_td)
                    c_lo = math.sqrt(1.0 - s_lo * s_lo)
                    inv_wh = 1.0 / wh
                    lin = omega * (1.0 - 2.0 * a) * inv_wh
                    amp = 2.0 * b * omega * inv_wh
                    q_r_b = l0 * (1.0 + a - b)
                    out[i, 0] = (ph_b - ph_td) * inv_wh
                    out[i, 1] = (ph_lo - ph_td) * inv_wh
                    out[i, 2] = q_r_b
                    out[i, 3] = 0.0
                    out[i, 4] = q_th + lin * (ph_b - ph_td) - amp * c_td  # cos(ph_b) = 0
                    out[i, 5] = omega / (1.0 + a - b) ** 2
                    out[i, 6] = q_r_lo
                    out[i, 7] = l0 * b * wh * c_lo
                    out[i, 8] = q_th + lin * (ph_lo - ph_td) + amp * (c_lo - c_td)
                    out[i, 9] = omega / (1.0 + rho_lo) ** 2
                    if not abs(out[i, 8]) < 0.5 * math.pi:
                        code = FALL
                    else:
                        for j in range(10):
                            if not math.isfinite(out[i, j]):
                                code = NUMERICAL_RANGE
        if code != OK:
            for j in range(10):
                out[i, j] = np.nan
        status[i] = code


def stance_batch(td: np.ndarray, m: float, l0: float, k: float, g_s: float, q_r_lo: float):
    """Allocate the outputs and run the kernel (what a user of a hand-written kernel would call)."""
    out = np.empty((td.shape[0], 10))
    status = np.empty(td.shape[0], dtype=np.int64)
    geyer_stance_handwritten(td, m, l0, k, g_s, q_r_lo, out, status)
    return out, status
