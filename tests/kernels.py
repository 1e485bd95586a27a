"""Calling a generated kernel by its arguments' names in tests, whatever its calling convention.

The generator chooses each kernel's convention (derive/lower.py's ``abi``): a role kernel takes its
layouts ``(x, p, out)``; another kernel takes up to 16 scalars, else one array of them, and returns
a tuple of up to 16 values, else writes them into an array ``out``. The tests call kernels by the
names of their declared arguments (the IR, ``slipmaps generate``'s modules) and read results by
the names of their declared outputs, so they do not restate any of that.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping, Sequence
from functools import cache

import numpy as np
from slipmaps.derive import generate
from slipmaps.derive.ir import Kernel
from slipmaps.derive.lower import abi
from slipmaps.derive.params import APEX_INPUTS, PARAMETERS

#: An apex-return input a test does not give takes its row's default (derive/params.py): the
#: tests written before an input existed call the kernels as they did.
DEFAULTS = {r["arg"]: float(r["default"]) for r in APEX_INPUTS if "default" in r}
#: The parameters the report's model leaves out (the leg damping c) at the value it assumes: a
#: parameter record's field not given takes it (every other field not given is NaN).
UNMODELLED = {r["name"]: float(r["unmodelled"]) for r in PARAMETERS if "unmodelled" in r}


def _value(values: Mapping[str, float], name: str) -> float:
    """The argument ``name``: given, else the input's default or the value the report's model assumes
    (:data:`UNMODELLED`; a missing required one: KeyError)."""
    if name in values:
        return float(values[name])
    if name in DEFAULTS:
        return DEFAULTS[name]
    if name in UNMODELLED:
        return UNMODELLED[name]
    return float(values[name])


@cache
def declared(jacobians: bool = True) -> dict[tuple[str, str], Kernel]:
    """Every generated kernel's declaration by (module, name); without the Jacobians' modules unless
    ``jacobians`` (their derivation is a third of a build)."""
    mods = generate.modules() if jacobians else generate.primal_modules()
    return {(k.module, k.name): k for mod in mods for k in mod.kernels()}


def declaration(module: str, name: str) -> Kernel:
    module = module.rsplit(".", 1)[-1]
    return declared(jacobians=module.endswith("_jacobian"))[(module, name)]


def function(kernel: Kernel):
    """The generated function of a declared kernel."""
    return getattr(importlib.import_module(f"slipmaps.generated.{kernel.module}"), kernel.name)


def invoke(kernel: Kernel, values: Mapping[str, float], fn=None) -> tuple:
    """``kernel`` at the arguments ``values`` (by name; a role kernel's parameter record takes the
    fields it does not read as NaN): its outputs in order, then its status when it has one (a kernel
    of one output and no status: that value alone). ``fn``: another function of the kernel's
    convention to call instead (its ``.py_func``)."""
    fn = function(kernel) if fn is None else fn
    how = abi(kernel)
    n_out = len(kernel.output_names)
    if how.layout is not None:
        return call_layouts(fn, how.layout.x, how.layout.p, n_out, values)
    args = [_value(values, a) for a in kernel.arg_names]
    if how.args_array:
        args = [np.array(args)]
    if how.out_array:
        out = np.empty(n_out)
        status = fn(*args, out)
        return (*map(float, out), int(status))
    return fn(*args)


def call_layouts(fn, x: Sequence[str], p: Sequence[str], width: int, values: Mapping[str, float]) -> tuple:
    """A role kernel ``fn(x, p, out) -> status`` with its layouts filled by name from ``values``
    (``x`` the inputs' names, ``p`` the parameter record's: a field not given is NaN, or the value
    the report's model assumes, :data:`UNMODELLED`); its ``width`` outputs, then its status."""
    xs = np.array([_value(values, a) for a in x])
    ps = np.array([float(values.get(f, UNMODELLED.get(f, math.nan))) for f in p] or [math.nan])
    out = np.empty(width)
    status = fn(xs, ps, out)
    return (*map(float, out), int(status))


def outputs(kernel: Kernel, result: tuple) -> dict[str, float]:
    """A result of :func:`invoke` by output name (the status left out)."""
    values = result if isinstance(result, tuple) else (result,)
    return dict(zip(kernel.output_names, values, strict=False))
