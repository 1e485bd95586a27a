"""Compile slipmaps' kernels once into numba's disk cache before the test workers start.

On an empty cache most of a first run of the suite is numba compiling kernels, and with
``pytest -n N`` every worker compiled the same kernels: N times the work, on the same cores. The
suite's controller (tests/conftest.py) calls :func:`warm` first: ``slipmaps warmup``'s mechanism
(``slipmaps.runtime.control.warmup``: the cold jobs in subprocesses, longest first, a progress bar
on a terminal) on its jobs, and the jobs of the kernels tests call beyond the API's
(:func:`kernel_jobs`): the other choices of a specialized option and the exact simulator's
external kernels, each of which a worker compiled for itself before. The workers then load the
kernels from the cache. With a warm cache it imports the generated modules and reads their cache
indexes: no subprocess.

What no entry can serve, every process that needs it compiles: the deadbeat solver bound to a
map's kernels, test-local closures (test_exact_compiled.py's integrator runs) and the modules
test_ir.py generates for itself.

The subprocesses are a plain ``python tests/warmup.py --worker`` reading job names on standard
input (:func:`slipmaps.runtime.control.warmup.worker` with :func:`jobs`).
"""

from __future__ import annotations

import os
import sys
from functools import cache

from slipmaps.runtime.control import warmup

#: Roles whose kernels tests call at every choice of a specialized option (the zeroth iterate of
#: ``iterative``), not only at its default: True with the batch form. test_codegen.py runs every
#: scalar kernel of the map modules, test_accuracy.py the stance's batch form at every zeroth
#: iterate (the accuracy record), test_jacobian.py the stance Jacobian at every option choice,
#: test_c_export.py every role's row kernel at every choice.
CHOICE_ROLES = {"stance": True, "apex_return": False, "stance_jacobian": False, "apex_return_jacobian": False}
#: The exact simulator's external kernels (generated/exact_stance.py) that tests call directly
#: (test_exact_compiled.py, test_exact_rtol.py); each inlines the DOP853 integrator.
EXACT_KERNELS = (
    "stance_jacobian",
    "stance_into",
    "stance",
    "decompression",
    "state_at",
    "compression",
    "stance_evaluations",
)


def _external_types(function) -> tuple:
    """The types tests call an external kernel of exact_stance with: float64 scalars, ``s`` its
    parameter record (``Stance``, float64 fields), ``out`` a C-contiguous float64 array."""
    import inspect

    import numba
    import numpy as np
    from slipmaps.generated import exact_stance

    record = exact_stance.Stance(*[0.0] * len(exact_stance.Stance._fields))
    by_name = {"s": numba.typeof(record), "out": numba.typeof(np.empty(1))}
    names = inspect.signature(function.py_func).parameters
    return tuple(by_name.get(name, numba.float64) for name in names)


def kernel_jobs() -> dict[str, list[tuple]]:
    """The jobs of one kernel (``module:function``) that tests call beyond the API's jobs
    (:data:`CHOICE_ROLES`, :data:`EXACT_KERNELS`): ``(function, argument types)`` to compile."""
    from slipmaps.generated import exact_stance
    from slipmaps.runtime.api import index

    out: dict[str, list[tuple]] = {}
    for m in (*index.maps(), *index.halves()):
        for suffix in sorted(set(m.choices.values())):
            for role, rows in CHOICE_ROLES.items():
                default = m.kernels.get(role)
                spec = default.chosen(suffix) if default is not None else None
                if spec is not None and spec.name != default.name:
                    out[f"{spec.module}:{spec.name}"] = warmup.signatures(spec, rows=rows)
    for name in EXACT_KERNELS:
        function = getattr(exact_stance, name)
        out[f"exact_stance:{name}"] = [(function, _external_types(function))]
    return out


@cache
def jobs() -> dict[str, list[tuple]]:
    """Every job of the suite: the API's (:func:`slipmaps.runtime.control.warmup.jobs`) and
    :func:`kernel_jobs`, as ``(function, argument types, bound)``."""
    out = dict(warmup.jobs())
    for job, work in kernel_jobs().items():
        out[job] = [(f, types, False) for f, types in work]
    return out


def warm(processes: int, say=print) -> warmup.Warmed:
    """The suite's cold jobs compiled in ``processes`` subprocesses (``slipmaps warmup``'s
    mechanism), a bar on standard error when it is a terminal."""
    command = [sys.executable, os.path.abspath(__file__), "--worker"]
    return warmup.warm(processes, table=jobs(), command=command, say=say)


if __name__ == "__main__":
    if sys.argv[1:] == ["--worker"]:
        sys.exit(warmup.worker(jobs()))
    warm(int(sys.argv[1]) if len(sys.argv) > 1 else (os.cpu_count() or 1))
