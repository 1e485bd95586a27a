"""The model's kernels by name: the exact flights, the equations of motion, the energy, the coordinate
maps (the generated index's ``MODEL``; ``slipmaps.generated.model``), for the runtime layers that
need them outside a map (the plant of a run, the solve_ivp reference, the studies, the command
line's flight report).

:func:`call` runs one with scalar inputs, :func:`rows` over arrays (broadcast against each other),
:func:`bind` gives a fast function of some inputs (the others fixed) for code calling one kernel
many times; all take the inputs by the kernel's argument names and return its outputs by name with a status
(a per-row status array for :func:`rows`). An apex-return input left out takes its default from
the inputs table (``derive/params.py``: ``retraction_rate`` 0, ``ground`` 0); another is an error
naming it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from slipmaps.derive import params as _table
from slipmaps.generated.status import Status

from .batch import run_rows
from .calls import kernel_functions
from .index import model_kernels

__all__ = ["bind", "call", "outputs", "rows"]

#: The defaults of the apex-return inputs that have one, by kernel argument.
_DEFAULTS = {r["arg"]: float(r["default"]) for r in _table.APEX_INPUTS if "default" in r}


def _spec(name: str):
    specs = model_kernels()
    if name not in specs:
        raise ValueError(f"unknown model kernel {name!r}; the model kernels are: {', '.join(specs)}")
    return specs[name]


def _value(spec, inputs: Mapping, arg: str):
    if arg in inputs:
        return inputs[arg]
    if arg in _DEFAULTS:
        return _DEFAULTS[arg]
    raise ValueError(f"model kernel {spec.name!r} needs input {arg!r} (its inputs: {', '.join(spec.x)})")


def call(name: str, **inputs) -> tuple[Status, dict[str, float]]:
    """``(status, outputs by name)`` of model kernel ``name`` at scalar ``inputs`` (by argument
    name); the outputs are NaN unless the status is OK."""
    spec = _spec(name)
    unknown = sorted(set(inputs) - set(spec.x))
    if unknown:
        raise ValueError(f"model kernel {name!r} has no input(s) {unknown} (its inputs: {', '.join(spec.x)})")
    x = np.array([float(_value(spec, inputs, a)) for a in spec.x])
    out = np.empty(spec.width)
    status = kernel_functions(spec)[0](x, np.empty(max(1, len(spec.p))), out)
    return Status(int(status)), dict(zip(spec.outputs, map(float, out), strict=True))


def rows(name: str, **inputs) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """``(status, outputs by name)`` of model kernel ``name`` over arrays (``inputs`` by argument
    name, broadcast against each other, flattened): a status per row (int64 codes) and an array per
    output."""
    spec = _spec(name)
    unknown = sorted(set(inputs) - set(spec.x))
    if unknown:
        raise ValueError(f"model kernel {name!r} has no input(s) {unknown} (its inputs: {', '.join(spec.x)})")
    parts = np.broadcast_arrays(*(np.asarray(_value(spec, inputs, a), dtype=float) for a in spec.x))
    n = int(parts[0].size)
    X = np.empty((n, len(spec.x)))
    for j, part in enumerate(parts):
        X[:, j] = part.reshape(n)
    out = np.empty((n, spec.width))
    status = np.empty(n, dtype=np.int64)
    run_rows(kernel_functions(spec)[1], X, np.empty((1, max(1, len(spec.p)))), out, status)
    return status, {o: out[:, j] for j, o in enumerate(spec.outputs)}


def bind(name: str, varying: tuple[str, ...], **fixed) -> callable:
    """Model kernel ``name`` as a function of the array of its inputs ``varying`` (by name, in that
    order), the others ``fixed`` (or their defaults): ``f(values) -> (status, out)``, ``out`` a new
    array of the kernel's outputs (NaN unless OK). For code that calls one kernel many times (the
    solve_ivp reference's vector field): the inputs are placed by name once."""
    spec = _spec(name)
    unknown = sorted((set(varying) | set(fixed)) - set(spec.x))
    if unknown:
        raise ValueError(f"model kernel {name!r} has no input(s) {unknown} (its inputs: {', '.join(spec.x)})")
    x = np.array([math.nan if a in varying else float(_value(spec, fixed, a)) for a in spec.x])
    at = np.array([spec.x.index(a) for a in varying], dtype=np.int64)
    p = np.empty(max(1, len(spec.p)))
    kernel = kernel_functions(spec)[0]
    width = spec.width

    def f(values):
        x[at] = values
        out = np.empty(width)
        return kernel(x, p, out), out

    return f


def outputs(name: str) -> tuple[str, ...]:
    """The output names of model kernel ``name``, in the order of its ``out``."""
    return _spec(name).outputs
