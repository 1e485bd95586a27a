"""Exact stance derivatives (generated/exact_stance.py, through slipmaps.stance_jacobian("exact")):
the variational equations of (2)-(3) with saltation matrices at the bottom (k_c -> k_d) and at
liftoff, against central differences of the compiled simulator itself (generated/exact_stance.py).

Central-difference step: h = 1e-5 times each input's scale (l0, sqrt(g_s l0), 1 rad, sqrt(g_s/l0),
k_c, k_d, and for the damping c its critical value 2 sqrt(k_c m)), the best of 1e-4 ... 1e-7
measured on every case below (truncation error ~ h^2 above,
the integrator's round-off ~ 3e-15 / h below). Error measure: per input column, max |FD - J| over
the 10 outputs divided by the column's largest |J|. The damping's column with c > 0 (and at c = 0,
a one-sided derivative) is tested in test_damping.py; here every case has c = 0 and its c column
is skipped (c - h is outside the domain).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
from slipmaps.generated import exact_stance as ej
from slipmaps.generated.status import Status
from slipmaps.runtime.api import model
from slipmaps.runtime.api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams

FD_STEP = 1e-5


def _touchdown(p: SlipParams, height: float, speed: float, angle: float) -> tuple[float, ...]:
    _, td = model.call(
        "apex_to_touchdown", b_y_apex=height, b_xd_apex=speed, q_th_td=angle, q_r_td=p.q_r_td, g_f=p.g_f
    )
    return tuple(td[f"touchdown_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd"))


SYMMETRIC_ANGLE = 0.41116492751713  # the human runner's symmetric fixed point at 1 m, 5 m/s
ROBOT_SHORT = ROBOT_HOPPER.with_(q_r_td=0.24)
#: (params, touchdown): symmetric and nonsymmetric, k_c == k_d and k_c != k_d. A touchdown at
#: q_r = l0 cannot be perturbed upward (q_r > l0 is outside the domain): its q_r column is skipped.
CASES = [
    pytest.param(HUMAN_RUNNER, _touchdown(HUMAN_RUNNER, 1.0, 5.0, SYMMETRIC_ANGLE), id="human-symmetric"),
    pytest.param(HUMAN_RUNNER, (0.99, -1.5, 0.35, -4.5), id="human-nonsymmetric"),
    pytest.param(HUMAN_RUNNER.with_(k_d=25_000.0), (0.99, -1.5, 0.35, -4.5), id="human-kd25k"),
    pytest.param(
        HUMAN_RUNNER.with_(k_d=17_000.0),
        _touchdown(HUMAN_RUNNER, 1.0, 5.0, SYMMETRIC_ANGLE),
        id="human-kd17k-symmetric-touchdown",
    ),
    pytest.param(ROBOT_SHORT, _touchdown(ROBOT_SHORT, 0.26, 1.5, 0.30), id="robot"),
    pytest.param(
        ROBOT_SHORT.with_(k_c=1_200.0, q_r_lo=0.23),
        _touchdown(ROBOT_SHORT, 0.26, 1.2, 0.35),
        id="robot-kc1.2k",
    ),
]


def stance_outputs(p: SlipParams, w: np.ndarray, **options) -> np.ndarray:
    stiffness = p.with_(k_c=w[ej.K_C], k_d=w[ej.K_D], c=w[ej.C])
    res = slipmaps.stance("exact", stiffness, w[: ej.N_POLAR], **options)
    assert res.status == Status.OK
    return np.array([res.values[n] for n in ej.STANCE_NAMES])


@pytest.mark.parametrize(("params", "touchdown"), CASES)
def test_jacobian_matches_central_differences(params, touchdown):
    jac = slipmaps.stance_jacobian("exact", params, touchdown)
    assert jac.status == Status.OK
    p = params
    w0 = np.array([*touchdown, p.k_c, p.k_d, p.c])
    columns = [j for j in range(ej.N_IN) if not (j == 0 and touchdown[0] >= p.l0) and j != ej.C]
    worst = worst_column_error(p, w0, jac.matrix, columns)
    # Measured over CASES: 2.1e-10 to 1.0e-9 (at h = 1e-4: up to 1.5e-7; at 1e-7: up to 1.4e-7).
    assert worst < 3e-8, worst


def _scale(p: SlipParams) -> np.ndarray:
    """Each input's scale (module docstring), in :data:`ej.INPUTS` order."""
    critical = 2.0 * math.sqrt(p.k_c * p.m)
    return np.array([p.l0, math.sqrt(p.g_s * p.l0), 1.0, math.sqrt(p.g_s / p.l0), p.k_c, p.k_d, critical])


def worst_column_error(p: SlipParams, w0: np.ndarray, matrix: np.ndarray, columns, **options) -> float:
    """The largest, over ``columns``, max |central difference - J| / max |J| of the column (the
    stance with ``options``)."""
    scale = _scale(p)
    worst = 0.0
    for j in columns:
        step = np.zeros(ej.N_IN)
        step[j] = FD_STEP * scale[j]
        fd = (stance_outputs(p, w0 + step, **options) - stance_outputs(p, w0 - step, **options)) / (
            2 * step[j]
        )
        worst = max(worst, float(np.max(np.abs(fd - matrix[:, j])) / np.max(np.abs(matrix[:, j]))))
    return worst


@pytest.mark.parametrize(("params", "touchdown"), CASES)
def test_values_are_the_exact_maps_and_the_structure_holds(params, touchdown):
    jac = slipmaps.stance_jacobian("exact", params, touchdown)
    assert jac.values == slipmaps.stance("exact", params, touchdown).values  # same steps, same events
    # The compression does not see k_d; the bottom stays on q_rd = 0 and liftoff on q_r = q_r_lo.
    assert np.all(jac["bottom", "k_d"] == 0.0) and jac["t_bottom", "k_d"] == 0.0
    for state, on_surface in (("bottom", "bottom_q_rd"), ("liftoff", "liftoff_q_r")):
        ratio = np.max(np.abs(jac[on_surface, "touchdown"])) / np.max(np.abs(jac[state, "touchdown"]))
        assert ratio < 1e-15, (state, ratio)  # measured: at most 6.2e-18
    assert jac["liftoff", "touchdown"].shape == (4, 4) and jac["liftoff", "k_d"].shape == (4,)
    assert jac["t_stance", "touchdown"].shape == (4,) and isinstance(jac["t_stance", "k_c"], float)


def test_batch_rows_equal_scalar_calls_and_failures_are_nan():
    p = HUMAN_RUNNER.with_(k_d=9_000.0)
    vertical = _touchdown(p, 1.1, 0.0, 0.0)  # RECOMPRESSION with the soft k_d (test_simulator.py)
    rows = np.array([(0.99, -1.5, 0.35, -4.5), vertical, (1.0, 0.5, 0.3, -4.0), (math.nan, -1.0, 0.3, -4.0)])
    batch = slipmaps.stance_jacobian_batch("exact", p, rows)
    out = np.column_stack([batch.result[n] for n in ej.STANCE_NAMES])
    jac, status = batch.matrix, batch.status
    expected = [Status.OK, Status.RECOMPRESSION, Status.TOUCHDOWN_NOT_COMPRESSING, Status.INVALID_INPUT]
    assert list(status) == expected
    one = slipmaps.stance_jacobian("exact", p, rows[0])
    values = one.values
    assert one.status == Status.OK and np.array_equal(jac[0], one.matrix)
    assert np.array_equal(out[0], [values[n] for n in ej.STANCE_NAMES])
    assert np.isnan(out[1:]).all() and np.isnan(jac[1:]).all()
    one = slipmaps.stance_jacobian("exact", p, vertical)
    assert one.status == Status.RECOMPRESSION and np.isnan(one.matrix).all()
    with pytest.raises(ValueError, match="q_r"):
        slipmaps.stance_jacobian("exact", p, (1.2, -1.0, 0.3, -4.0))
    with pytest.raises(KeyError, match="apex"):
        _ = one["apex", "k_c"]


#: The parity of each output (t_bottom, t_stance, bottom, liftoff) and input (touchdown, k_c, k_d, c)
#: under the mirror x -> -x, (q_th, q_thd) -> (-q_th, -q_thd).
_STATE_PARITY = (1.0, 1.0, -1.0, -1.0)
OUT_PARITY = np.array([1.0, 1.0, *_STATE_PARITY, *_STATE_PARITY])
IN_PARITY = np.array([*_STATE_PARITY, 1.0, 1.0, 1.0])
SIGNS = OUT_PARITY[:, None] * IN_PARITY[None, :]


@pytest.mark.parametrize(("params", "touchdown"), CASES)
def test_jacobian_is_mirror_symmetric(params, touchdown):
    """d(out_i)/d(in_j) of the mirrored touchdown is parity(out_i) parity(in_j) times the original's."""
    mirror = tuple(np.array(touchdown) * IN_PARITY[:4])
    jac = slipmaps.stance_jacobian("exact", params, touchdown)
    jac_m = slipmaps.stance_jacobian("exact", params, mirror)
    assert jac.status == jac_m.status == Status.OK
    # Measured over CASES: 0 (bitwise).
    scale = np.max(np.abs(jac.matrix), axis=0)
    assert np.max(np.abs(jac_m.matrix - SIGNS * jac.matrix) / scale) < 1e-14


def test_vertical_hop_jacobian_has_no_mixed_parity_entries():
    """At q_th = q_thd = 0 the mirror fixes the touchdown: entries coupling even and odd parities
    are exactly 0, the others are not."""
    p = HUMAN_RUNNER.with_(k_d=25_000.0)
    jac = slipmaps.stance_jacobian("exact", p, (0.99, -1.5, 0.0, 0.0))
    assert jac.status == Status.OK
    assert np.all(jac.matrix[SIGNS < 0] == 0.0)
    even = ("t_stance", "liftoff_q_rd")  # liftoff_q_r stays on the surface q_r = q_r_lo
    odd = ("liftoff_q_th", "liftoff_q_thd")
    even_in, odd_in = ("q_r_td", "q_rd_td", "k_c", "k_d"), ("q_th_td", "q_thd_td")
    assert all(jac[o, i] != 0.0 for o in even for i in even_in)
    assert all(jac[o, i] != 0.0 for o in odd for i in odd_in)
