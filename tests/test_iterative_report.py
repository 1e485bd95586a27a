"""Schwind and Koditschek's iteration as the report prints it (map ``"iterative-report"``, report
sections 3.2 and 5.2), through the public API.

* An iterate whose H^{-1} of (33) is imaginary returns IMAGINARY_MOMENTUM, never NaN with OK.
* iterations = 0 is the zeroth iterate: the chosen map's bottom and liftoff angles (Geyer et al.'s
  by default, or the held touchdown angle).
* The chain equals the report's recursion (42)-(44)/(124)-(126) and (133)-(135)/(148)-(150), written
  here as a recursion on functions of the leg length.
* Variable stiffness (k_c != k_d) is accepted; the two mean-value variants differ.

Accuracy against the exact stance is measured by ``slipmaps accuracy``, not here.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import slipmaps
from slipmaps import SlipParams, Status
from slipmaps.runtime.api import index

MAP = "iterative-report"
#: The Yu protocol's runner (kappa = k l0/(m g) = 10).
YU = SlipParams(m=80.0, l0=1.0, k=7848.0)
#: A 30 degree touchdown of that protocol (rates rounded): real iterates up to n = 2 with
#: "integrand", imaginary H^{-1} from n = 3 (measured).
STEEP = (1.0, -2.1116, 0.5236, -1.0903)
#: A shallow touchdown: every iterate real for n <= 8, both variants (measured).
SHALLOW = (1.0, -1.2, 0.3142, -3.0)
#: A slow touchdown where every zeroth-iterate choice gives a real H^{-1} at n = 0, both variants
#: (measured; at SHALLOW the gravity corrections' types 0-4 already give IMAGINARY_MOMENTUM there).
SLOW = (1.0, -2.0, 0.3142, -2.0)


def test_imaginary_momentum_is_a_status_not_nan():
    ok = slipmaps.stance(MAP, YU, STEEP, iterations=2)
    assert ok.status == Status.OK and all(math.isfinite(v) for v in ok.liftoff)
    res = slipmaps.stance(MAP, YU, STEEP, iterations=3)
    assert res.status == Status.IMAGINARY_MOMENTUM, res.message
    assert all(math.isnan(v) for v in res.liftoff)
    batch = slipmaps.stance_batch(MAP, YU, np.array([STEEP, SHALLOW]), iterations=3)
    assert list(batch["status"]) == [Status.IMAGINARY_MOMENTUM, Status.OK]


def _zeroth_choices(name: str) -> tuple[str, ...]:
    return index.lookup(name).option("zeroth").choices


@pytest.mark.parametrize("zeroth", _zeroth_choices(MAP))
def test_zeroth_iterate_is_the_chosen_map(zeroth):
    """iterations = 0 is the zeroth iterate: the chosen map's bottom and liftoff (at its defaults),
    or the touchdown state held."""
    for variant in ("integrand", "factor"):
        res = slipmaps.stance(MAP, YU, SLOW, iterations=0, variant=variant, zeroth=zeroth)
        assert res.ok, res.message
        if zeroth == "held":
            assert res["bottom_q_th"] == res["liftoff_q_th"] == SLOW[2]
            continue
        chosen = slipmaps.stance(zeroth, YU, SLOW)
        assert res["bottom_q_r"] == chosen["bottom_q_r"]
        for key in ("bottom_q_th", "liftoff_q_th", "liftoff_q_thd"):
            assert res[key] == pytest.approx(chosen[key], rel=1e-14), key


def _reference(params: SlipParams, td: tuple, n: int, variant: str) -> tuple[float, ...]:
    """The report's recursion, the (k+1)-th iterate at x from the k-th at xi(x), with Geyer's zeroth
    iterate: (t_bottom, bottom_q_th, bottom_q_thd, t_stance, liftoff_q_th, liftoff_q_thd, liftoff_q_rd)."""
    m, l0, g = params.m, params.l0, params.g_s
    r, rd, th, thd = td
    geyer = slipmaps.stance("geyer", SlipParams(m=m, l0=l0, k=params.k_c, g_s=g), td)
    r_b, r_lo = geyer["bottom_q_r"], params.q_r_lo
    p_td, p_b0 = m * r**2 * thd, m * r_b**2 * geyer["bottom_q_thd"]
    e_ab = 0.5 * m * (rd**2 + r**2 * thd**2) + 0.5 * params.k_c * (l0 - r) ** 2 + m * g * r * math.cos(th)
    e_ba = e_ab + 0.5 * (params.k_d - params.k_c) * (l0 - r_b) ** 2

    def h_inv(k, energy, x, q, p):
        return math.sqrt(2 * m * (energy - 0.5 * k * (l0 - x) ** 2 - m * g * x * math.cos(q)) - p**2 / x**2)

    def step(k, energy, sign, a, t_a, q_a, p_a, xi, x, q, p):
        h = sign * h_inv(k, energy, xi, q, p)
        if variant == "integrand":
            return (
                t_a + m / h * (x - a),
                q_a + p / (xi**2 * h) * (x - a),
                p_a + m * m * g * xi * math.sin(q) / h * (x - a),
            )
        return (
            t_a + m / h * (x - a),
            q_a + p / h * (1 / a - 1 / x),
            p_a + m * m * g * math.sin(q) / (2 * h) * (x * x - a * a),
        )

    def compression(j, x):  # anchored at touchdown, xi = 3/4 q_r_td + 1/4 x (123)
        if j == 0:
            u = math.sqrt((x - r_b) / (r - r_b))
            return None, geyer["bottom_q_th"] + (th - geyer["bottom_q_th"]) * u, p_b0 + (p_td - p_b0) * u
        xi = 0.75 * r + 0.25 * x
        return step(params.k_c, e_ab, -1, r, 0.0, th, p_td, xi, x, *compression(j - 1, xi)[1:])

    t_b, q_b, p_b = compression(n, r_b)
    p_lo0 = m * r_lo**2 * geyer["liftoff_q_thd"]

    def decompression(j, x):  # anchored at the bottom, xi = 3/4 q_r_b + 1/4 x (41)
        if j == 0:
            u = math.sqrt((x - r_b) / (r_lo - r_b))
            return None, q_b + (geyer["liftoff_q_th"] - q_b) * u, p_b + (p_lo0 - p_b) * u
        xi = 0.75 * r_b + 0.25 * x
        return step(params.k_d, e_ba, 1, r_b, t_b, q_b, p_b, xi, x, *decompression(j - 1, xi)[1:])

    t_lo, q_lo, p_lo = decompression(n, r_lo)
    p_r_lo = h_inv(params.k_d, e_ba, r_lo, q_lo, p_lo)
    return t_b, q_b, p_b / (m * r_b**2), t_lo, q_lo, p_lo / (m * r_lo**2), p_r_lo / m


@pytest.mark.parametrize("variant", ["integrand", "factor"])
@pytest.mark.parametrize("n", [1, 2, 5])
def test_chain_is_the_reports_recursion(variant, n):
    params = SlipParams(m=80.0, l0=1.0, k_c=7848.0, k_d=9000.0)
    res = slipmaps.stance(MAP, params, SHALLOW, iterations=n, variant=variant)
    assert res.ok, res.message
    got = [res[k] for k in ("t_bottom", "bottom_q_th", "bottom_q_thd", "t_stance")]
    got += [res[k] for k in ("liftoff_q_th", "liftoff_q_thd", "liftoff_q_rd")]
    # measured: 1e-15 relative
    assert got == pytest.approx(_reference(params, SHALLOW, n, variant), rel=1e-12)


def test_variable_stiffness_accepted():
    same = slipmaps.stance(MAP, YU, SHALLOW, iterations=2)
    stiffer = slipmaps.stance(MAP, SlipParams(m=80.0, l0=1.0, k_c=7848.0, k_d=9000.0), SHALLOW, iterations=2)
    assert same.ok and stiffer.ok, stiffer.message
    assert stiffer.bottom == same.bottom  # the compression half sees k_c only
    assert stiffer["liftoff_q_rd"] > same["liftoff_q_rd"]  # E_ba of (98) gains (k_d - k_c)/2 (l0 - q_r_b)^2


def test_variants_differ():
    a = slipmaps.stance(MAP, YU, SHALLOW, iterations=2, variant="integrand")
    b = slipmaps.stance(MAP, YU, SHALLOW, iterations=2, variant="factor")
    assert a.ok and b.ok
    assert a["liftoff_q_th"] != pytest.approx(b["liftoff_q_th"], rel=1e-6)
    assert a["bottom_q_thd"] != pytest.approx(b["bottom_q_thd"], rel=1e-6)
    assert a["t_stance"] == pytest.approx(b["t_stance"], rel=0.1)  # same time formula, other iterates


@pytest.mark.parametrize("variant", ["integrand", "factor"])
def test_eq124_eq126_compression_half_is_the_whole_maps_bottom(variant):
    params = SlipParams(m=80.0, l0=1.0, k_c=7848.0, k_d=9000.0)
    whole = slipmaps.stance(MAP, params, SHALLOW, iterations=2, variant=variant)
    half = slipmaps.half_stance(
        "iterative-report-compression", params, SHALLOW, iterations=2, variant=variant
    )
    assert whole.ok and half.ok, half.message
    assert half["end"] == whole.bottom and half["t_half"] == whole.t_bottom


def _energy(params: SlipParams, k: float, state) -> float:
    r, rd, th, thd = state
    return (
        0.5 * params.m * (rd**2 + r**2 * thd**2)
        + 0.5 * k * (params.l0 - r) ** 2
        + params.m * params.g_s * r * math.cos(th)
    )


@pytest.mark.parametrize("variant", ["integrand", "factor"])
def test_eq137_eq151_decompression_half_keeps_the_bottom_energy(variant):
    """From a bottom state, E_ba of (137) is that state's energy with k_d, and the liftoff p_r is
    H^{-1} at q_r_lo on it ((45) corrected): the liftoff state has the bottom's energy (measured
    2e-16 relative); n = 0 holds the bottom's angle."""
    params = SlipParams(m=80.0, l0=1.0, k_c=7848.0, k_d=9000.0)
    bottom = slipmaps.stance("exact", params, SHALLOW).bottom
    name = "iterative-report-decompression"
    for n in (0, 1, 2):
        res = slipmaps.half_stance(name, params, bottom, iterations=n, variant=variant)
        assert res.ok, res.message
        assert _energy(params, params.k_d, res["end"]) == pytest.approx(
            _energy(params, params.k_d, (bottom[0], 0.0, *bottom[2:])), rel=1e-12
        )
    held = slipmaps.half_stance(name, params, bottom, iterations=0, variant=variant)
    assert held["end_q_th"] == bottom[2]
