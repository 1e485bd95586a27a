"""The warm-up of numba's cache: ``slipmaps warmup`` (runtime/control/warmup.py; issue 52, item 3)
and the suite's (tests/warmup.py, tests/conftest.py; issue 32, item 7), one mechanism: it compiles
what the API calls, on every core, and runs for the whole suite in the controller only."""

from __future__ import annotations

import os
import sys
from types import SimpleNamespace

import conftest
import numba
import numpy as np
import pytest
import slipmaps
import warmup
from slipmaps.runtime.api import index, model
from slipmaps.runtime.control import warmup as api_warmup

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
        for function, types in api_warmup.signatures(spec):
            if function.signatures:  # called above (a model kernel's batch form was not)
                assert types in function.signatures, (function, types, function.signatures)
                checked += 1
    assert checked >= 4  # geyer's kernel and batch form, its Jacobian, the model kernel


def test_every_role_kernel_at_its_defaults_is_warmed():
    specs = api_warmup.role_specs()
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
        "stance_jacobian": (
            *td,
            P.m,
            P.l0,
            P.k_c,
            P.k_d,
            P.g_s,
            P.c,
            P.q_r_lo,
            1e-11,
            1e-12,
            float(ec.LIFTOFF_FORCE),
            np.empty(ec.N_STANCE * (1 + ec.N_IN)),
        ),  # fmt: skip
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
        assert api_warmup.solver_signature(types) == compiled.MODEL.signature


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
    monkeypatch.setattr(api_warmup, "cold_jobs", lambda *a, **k: [])
    monkeypatch.setattr(api_warmup, "_drive", lambda *a: pytest.fail("a warm-up process started"))
    said = []
    assert warmup.warm(2, say=said.append) == api_warmup.Warmed(jobs=0, seconds=0.0)
    assert said == []


def test_kernel_jobs_start_after_every_module_job_has_finished():
    """A kernel job (``module:function``) calls what the modules' jobs compile: it waits until every
    one of them has finished (not only been taken), so its callees load from the cache."""
    import threading

    phases = api_warmup.Phases(["control", "exact", "iterative:a", "geyer", "iterative:b"])
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


# --- slipmaps warmup: the command, the suite's warm-up, one mechanism -------------------------------

#: A warm-up subprocess that compiles nothing: each job done at once, but "bad", which fails.
FAKE_WORKER = (
    "import sys\n"
    "for line in sys.stdin:\n"
    "    job = line.strip()\n"
    "    if job == 'bad':\n"
    "        print('bad: RuntimeError: no such kernel', file=sys.stderr, flush=True)\n"
    "        print('failed bad', flush=True)\n"
    "    else:\n"
    "        print('done', job, '0.0', flush=True)\n"
)


def test_the_suite_and_the_command_share_one_warm_up(monkeypatch):
    """tests/warmup.py adds its jobs and its subprocess to ``slipmaps warmup``'s mechanism
    (runtime/control/warmup.py), which the command runs for the maps it is given."""
    from slipmaps.runtime.cli.app import main

    calls = []
    monkeypatch.setattr(api_warmup, "warm", lambda *a, **k: calls.append((a, k)) or api_warmup.Warmed())
    warmup.warm(2)
    (processes,), kwargs = calls[0]
    assert (
        processes == 2
        and kwargs["table"] is warmup.jobs()
        and kwargs["command"][1].endswith("tests/warmup.py")
    )
    assert main(["warmup", "geyer", "exact-compression", "--processes", "1", "--no-progress"]) == 0
    assert calls[1][0] == (1, ["geyer", "exact-compression"]) and calls[1][1]["progress"] is False


def test_the_warm_up_counts_its_jobs_on_a_bar_and_names_a_failed_one(monkeypatch, capsys):
    monkeypatch.setattr(api_warmup, "cold_jobs", lambda *a, **k: ["control", "geyer", "bad", "geyer:x_rows"])
    said = []
    done = api_warmup.warm(
        2, table={}, command=[sys.executable, "-c", FAKE_WORKER], say=said.append, progress=True
    )
    assert done.jobs == 4 and done.failed == ("bad: bad: RuntimeError: no such kernel",)
    err = capsys.readouterr().err
    assert "compiling slipmaps' kernels: [" in err and "4/4 jobs" in err and err.endswith("\n")
    assert said[0] == "warming numba's cache (empty or stale): 4 jobs in 2 processes"
    assert "not compiled (later calls compile them): bad: bad: RuntimeError: no such kernel" in said[1]


def test_warmup_with_maps_warms_those_maps_kernels_only():
    jobs = api_warmup.jobs(["geyer"])
    assert {job.split(":")[0] for job in jobs} == {"geyer", "geyer_jacobian"}
    assert "geyer_jacobian:geyer_apex_return_jacobian_rows" in jobs  # the Jacobian batch's own job
    assert all(
        f.py_func.__module__.startswith("slipmaps.generated.geyer") for w in jobs.values() for f, *_ in w
    )
    everything = api_warmup.jobs()
    assert "model" in everything and set(jobs) < set(everything)


@pytest.mark.parametrize(
    ("argv", "says"),
    [
        (["warmup", "nope"], "MAP: unknown map 'nope'; the maps are geyer, "),
        (["warmup", "--processes", "0"], "--processes must be a positive number of processes, got 0"),
    ],
)
def test_warmup_refuses_a_bad_argument_in_one_line(argv, says, capsys, monkeypatch):
    from slipmaps.runtime.cli.app import main

    monkeypatch.setattr(api_warmup, "warm", lambda *a, **k: pytest.fail("the warm-up started"))
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"slipmaps warmup: error: {says}") and err.count("\n") == 1, err


def test_warmup_on_a_warm_cache_says_so_and_starts_nothing(capsys, monkeypatch):
    from slipmaps.runtime.cli.app import main

    monkeypatch.setattr(api_warmup, "cold_jobs", lambda *a, **k: [])
    monkeypatch.setattr(api_warmup, "_drive", lambda *a: pytest.fail("a warm-up process started"))
    assert main(["warmup"]) == 0
    assert (
        capsys.readouterr().out == "numba's cache already holds every kernel asked for: nothing to compile\n"
    )
