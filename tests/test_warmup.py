"""The suite's warm-up of numba's cache (tests/warmup.py, tests/conftest.py; issue 32, item 7): it
compiles what the API calls, and runs for the whole suite in the controller only."""

from __future__ import annotations

import os
from types import SimpleNamespace

import conftest
import numba
import numpy as np
import pytest
import slipmaps
import warmup
from slipmaps.runtime.api import index, model

P = slipmaps.HUMAN_RUNNER


def test_the_warm_up_compiles_the_signatures_the_api_calls():
    """A cache entry is per argument types: the warm-up's must be the ones a call of the API looks
    up, else the workers compile everything again."""
    slipmaps.apex_return("geyer", P, 1.0, 5.0, 0.35)
    slipmaps.apex_return_batch("geyer", P, np.linspace(0.9, 1.1, 200), 5.0, 0.35)
    slipmaps.apex_return_jacobian("geyer", P, 1.0, 5.0, 0.35)
    energy = {
        "q_r": 1.0,
        "q_rd": -1.0,
        "q_th": 0.1,
        "q_thd": 1.0,
        "m": 80.0,
        "l0": 1.0,
        "k": 2e4,
        "g_s": 9.81,
    }
    model.call("stance_energy", **energy)
    geyer = index.get("geyer").kernels
    specs = [geyer["apex_return"], geyer["apex_return_jacobian"], index.model_kernels()["stance_energy"]]
    checked = 0
    for spec in specs:
        for function, types in warmup.signatures(spec):
            if function.signatures:  # called above (a model kernel's batch form was not)
                assert types in function.signatures, (function, types, function.signatures)
                checked += 1
    assert checked >= 4  # geyer's kernel and batch form, its Jacobian, the model kernel


def test_every_role_kernel_at_its_defaults_is_warmed():
    specs = warmup.role_specs()
    names = {(s.module, s.name) for kernels in specs.values() for s in kernels}
    for m in (*index.maps(), *index.halves()):
        for spec in m.kernels.values():
            assert (spec.module, spec.name) in names, (m.name, spec.name)
    assert all(("model", s.name) in names for s in index.model_kernels().values())


def test_the_kernel_jobs_are_the_kernels_and_types_the_tests_call():
    """Beyond the defaults: every other choice of a specialized option (the API picks its kernels
    by name), the exact simulator's external kernels at the types tests pass (float64 scalars, its
    parameter record, an output array), the Jacobians' batch forms."""
    from slipmaps.generated import exact_stance as ec

    jobs = warmup.jobs()
    for name in ("iterative", "iterative-report"):
        m = index.get(name)
        for choice in m.option("zeroth").choices:
            kernels = m.kernels_for(m.resolve({"zeroth": choice}))
            for role in warmup.CHOICE_ROLES:
                spec = kernels[role]
                assert f"{spec.module}:{spec.name}" in jobs or spec == m.kernels[role], (name, choice, role)
    for m in index.maps():
        for role in ("stance_jacobian", "apex_return_jacobian"):
            spec = m.kernels[role]
            assert [f for f, *_ in jobs[f"{spec.module}:{spec.name}_rows"]] == [spec.functions()[1]]
    record = ec.Stance(P.m, P.l0, P.k_c, P.k_d, P.g_s, P.q_r_lo, 1e-11, 1e-12, 1.0)
    td = (0.99, -1.5, 0.35, -4.5)
    called = {  # as test_exact_compiled.py and test_exact_rtol.py call them
        "stance_into": (*td, record, np.empty(ec.N_STANCE)),
        "stance_evaluations": (*td, record),
        "stance_jacobian": (*td, P.m, P.l0, P.k_c, P.k_d, P.g_s, P.q_r_lo, 1e-11, 1e-12, np.empty(70)),
    }
    for name, args in called.items():
        [(function, types, _)] = jobs[f"exact_stance:{name}"]
        assert function is getattr(ec, name) and types == tuple(map(numba.typeof, args)), name


def test_the_kernels_the_solver_binds_are_warmed_under_its_key():
    """The deadbeat solver compiles a kernel it binds at its full signature (compiled.MODEL, int64
    return type included), which numba's cache keys apart from a call's argument types."""
    from slipmaps.runtime.control import compiled

    bound = {f.py_func.__name__: types for work in warmup.jobs().values() for f, types, b in work if b}
    geyer, half = index.get("geyer").kernels, index.get_half("exact-decompression").kernels
    assert {geyer["apex_return"].name, geyer["apex_return_jacobian"].name, half["apex"].name} <= set(bound)
    for types in bound.values():
        assert warmup.solver_signature(types) == compiled.MODEL.signature


def _config(args, numprocesses=None, collectonly=False):
    option = SimpleNamespace(numprocesses=numprocesses, collectonly=collectonly)
    return SimpleNamespace(option=option, args=args)


@pytest.mark.parametrize(
    ("args", "numprocesses", "env", "expected"),
    [
        ([str(conftest.TESTS)], 2, {}, 2),  # pytest -n 2: one process per worker
        ([], None, {}, "cores"),  # pytest without xdist: the cores
        ([str(conftest.TESTS.parent)], 1, {}, 1),
        ([str(conftest.TESTS / "test_geyer.py")], 2, {}, 0),  # a subset compiles what it needs
        ([str(conftest.TESTS / "test_geyer.py")], 2, {"SLIPMAPS_WARMUP": "1"}, 2),
        ([str(conftest.TESTS)], 2, {"SLIPMAPS_WARMUP": "0"}, 0),
        ([str(conftest.TESTS)], 2, {"PYTEST_XDIST_WORKER": "gw0"}, 0),  # a worker: the controller warmed
    ],
)
def test_the_warm_up_runs_for_the_whole_suite_in_the_controller(
    args, numprocesses, env, expected, monkeypatch
):
    for name in ("SLIPMAPS_WARMUP", "PYTEST_XDIST_WORKER"):
        monkeypatch.delenv(name, raising=False)
    for name, value in env.items():
        monkeypatch.setenv(name, value)
    if expected == "cores":
        expected = os.cpu_count() or 1
    assert conftest._warmup_processes(_config(args, numprocesses)) == expected
    assert conftest._warmup_processes(_config(args, numprocesses, collectonly=True)) == 0


def test_a_warm_cache_starts_nothing(monkeypatch):
    monkeypatch.setattr(warmup, "cold_jobs", lambda: [])
    monkeypatch.setattr(warmup, "_drive", lambda *a: pytest.fail("a warm-up process started"))
    said = []
    assert warmup.warm(2, say=said.append) == 0.0
    assert said == []


def test_kernel_jobs_start_after_every_module_job_has_finished():
    """A kernel job (``module:function``) calls what the modules' jobs compile: it waits until every
    one of them has finished (not only been taken), so its callees load from the cache."""
    import threading

    phases = warmup.Phases(["control", "exact", "iterative:a", "geyer", "iterative:b"])
    assert [phases.take(), phases.take(), phases.take()] == ["control", "exact", "geyer"]
    got: list = []
    waiting = threading.Thread(target=lambda: got.append(phases.take()))
    waiting.start()
    for job in ("control", "geyer"):
        phases.finished(job)
    waiting.join(timeout=0.2)
    assert waiting.is_alive() and got == []  # "exact" is still running
    phases.finished("exact")
    waiting.join(timeout=10)
    assert got == ["iterative:a"]
    phases.finished("iterative:a")
    assert [phases.take(), phases.take()] == ["iterative:b", None]
