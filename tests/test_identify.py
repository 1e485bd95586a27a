"""Identification (runtime/control/identify.py): the derivatives it fits with, and known parameters
recovered from hops logged on the exact plant."""

from __future__ import annotations

import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.control.identify import Hops, _Model, hops_of
from slipmaps.runtime.control.runs import run_batch

P = slipmaps.HUMAN_RUNNER


def _hops(n: int, constant: bool, seed: int = 1) -> Hops:
    rng = np.random.default_rng(seed)
    k_d = np.full(n, P.k_c) if constant else rng.uniform(19_000.0, 23_000.0, n)
    return Hops(
        apex_height=rng.uniform(1.0, 1.2, n),
        apex_speed=rng.uniform(3.0, 6.0, n),
        touchdown_angle=rng.uniform(0.3, 0.36, n),
        ground=rng.uniform(-0.05, 0.05, n),
        k_c=np.full(n, P.k_c),
        k_d=k_d,
        retraction_rate=np.full(n, -0.5),
        next_apex_height=np.zeros(n),
        next_apex_speed=np.zeros(n),
    )


@pytest.mark.parametrize("name", ["exact", "iterative", "geyer", "gravity-type2"])
@pytest.mark.parametrize("fit", [("k", "l0", "loss"), ("m",)])
def test_identification_derivatives_agree_with_central_differences(name, fit):
    """d/dk and d/dm from the map's stiffness columns, d/dloss from its speed column and d/dl0 from
    the map's dimensional homogeneity (module docstring) against central differences of the map:
    measured at most 1.1e-8 relative on these maps (the differences' own error)."""
    model = _Model(name, P, fit, {})
    hops = _hops(6, model.constant)
    z = {k: v for k, v in {"k": 1.03, "l0": 0.98, "loss": 0.02, "m": 78.0}.items() if k in fit}
    pred, status, D = model.evaluate(z, hops, True)
    ok = status == 0
    assert ok.sum() >= 4
    for j, f in enumerate(fit):
        eps = 1e-6 * max(abs(z[f]), 1.0)
        up, down = dict(z), dict(z)
        up[f] += eps
        down[f] -= eps
        fd = (model.evaluate(up, hops, False)[0] - model.evaluate(down, hops, False)[0]) / (2 * eps)
        rel = np.abs(fd[ok] - D[ok, :, j]) / np.maximum(np.abs(fd[ok]), 1e-3)
        assert rel.max() < 1e-6, (f, rel.max())


@pytest.fixture(scope="module")
def mismatched():
    """Runs on the exact plant whose mass is 1.05 times the model's and whose springs are 1.1 times
    what is commanded: the maps see k / m, so the stiffness factor is 1.1 / 1.05."""
    sc = slipmaps.load_scenario("examples/speed_up.toml").with_(mismatch_mass=0.05, mismatch_stiffness=0.1)
    return run_batch(sc)


def test_identification_recovers_a_known_mismatch_on_the_exact_plant(mismatched):
    """Fitting k, l0 and the loss with the exact map recovers the factor 1.1 / 1.05, l0 and no loss
    (measured: 9e-10, 4e-10 and 6e-11); the identified model predicts the held-out hops to 1e-6 m
    where the nominal one misses by 14 mm on average."""
    got = slipmaps.identify(mismatched, map="exact", fit=("k", "l0", "loss"), holdout=0.3)
    assert got.k_factor == pytest.approx(1.1 / 1.05, rel=1e-7)
    assert got.fitted["l0"] == pytest.approx(P.l0, rel=1e-7)
    assert abs(got.loss) < 1e-7
    assert got.params.m == pytest.approx(P.m * 1.05 / 1.1, rel=1e-7) and got.params.k_c == P.k_c
    assert got.held_out == 5 and got.errors_fitted["held_out"]["count"] == 5
    assert got.errors_fitted["held_out"]["height_max"] < 1e-6
    assert got.errors_nominal["held_out"]["height_mean"] > 5e-3  # measured 14.5 mm
    assert "identified on exact from 16 hops (5 held out)" in got.summary()


def test_a_run_planned_on_the_identified_model_lands_on_its_targets(mismatched):
    """The identified model in the scenario (``Identified.scenario()``): the mismatched plant's next
    apexes land on the deadbeat targets within 1e-5 m and 3e-5 m/s (measured 4.1e-6 m and 1.4e-5
    m/s: iterative's own error against the exact plant), where the nominal model missed by up to
    29 mm and 41 mm/s. (A map plant is the model's parameters with the mismatch:
    the mass mismatch is set so that the plant stays the one the hops were logged on.)"""
    got = slipmaps.identify(mismatched, map="iterative", fit=("m",), holdout=0.0)
    same_plant = P.m * 1.05 / got.params.m - 1.0
    sc = mismatched.scenario.with_(**got.scenario(), mismatch_mass=same_plant)
    run = slipmaps.run(sc)
    dh, dv = run.errors()
    reached = run.column("plan_status") == 0
    assert not run.fell and reached.sum() >= 4
    assert np.max(np.abs(dh[reached])) < 1e-5 and np.max(np.abs(dv[reached])) < 3e-5


def test_identification_refuses_what_cannot_be_fitted(mismatched):
    with pytest.raises(ValueError, match="'k' and 'm' enter the maps only as k / m"):
        slipmaps.identify(mismatched, fit=("k", "m"))
    with pytest.raises(ValueError, match="unknown name 'mass'; the names are k, m, l0, loss"):
        slipmaps.identify(mismatched, fit=("mass",))
    with pytest.raises(ValueError, match="holdout must be a fraction in"):
        slipmaps.identify(mismatched, holdout=1.0)
    with pytest.raises(TypeError, match="runs must be RunBatch or Run objects"):
        slipmaps.identify([1, 2, 3])
    few = hops_of(mismatched).take(slice(0, 3))
    with pytest.raises(ValueError, match="at least 6 hops"):
        slipmaps.identify(few, fit=("k", "l0", "loss"), params=P)


def test_hops_of_a_run_are_its_ok_steps(mismatched):
    hops = hops_of(mismatched.run(0))
    assert len(hops) == 16 == int(mismatched.completed[0])
    assert np.array_equal(hops.next_apex_height, mismatched["next_apex_height"][0])
