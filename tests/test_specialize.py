"""Options with kernels per choice (``Option.specialize``, derive/specialize.py): each choice has its
own kernels, the option is not a kernel argument, the runtime calls the kernel of the choice, and a
first call of one choice compiles none of the other choices' kernels."""

from __future__ import annotations

import importlib
import itertools
import json
import os
import subprocess
import sys

import numpy as np
import pytest
import slipmaps
import sympy as sp
from slipmaps.derive.declaration import Option
from slipmaps.derive.ir import Arg, Field, Group, Guard, Kernel, Stage, Switch, sym
from slipmaps.derive.specialize import specialize
from slipmaps.runtime.api import index
from slipmaps.runtime.api.calls import Call

SPECIALIZED = [info for info in (*index.maps(), *index.halves()) if info.specialized]


def test_some_map_has_kernels_per_choice():
    assert {"iterative", "iterative-report"} <= {info.name for info in SPECIALIZED}
    assert all(info.option(o).specialize for info in SPECIALIZED for o in info.specialized)


@pytest.mark.parametrize("info", SPECIALIZED, ids=lambda i: i.name)
def test_every_choice_has_its_kernels_without_the_option_argument(info):
    keys = [",".join(c) for c in itertools.product(*(info.option(o).choices for o in info.specialized))]
    assert sorted(info.choices) == sorted(keys)
    names = set()
    for suffix in info.choices.values():
        for role, spec in info.kernels.items():
            chosen = spec.chosen(suffix)
            module = importlib.import_module(f"slipmaps.generated.{chosen.module}")
            assert callable(getattr(module, chosen.name)), (role, chosen.name)
            assert not set(info.specialized) & set(chosen.x + chosen.p), role
            names.add(chosen.name)
    assert len(names) == len(info.choices) * len(info.kernels)


@pytest.mark.parametrize("info", SPECIALIZED, ids=lambda i: i.name)
def test_the_call_picks_the_kernel_of_the_choice(info):
    """Each choice of each specialized option, the others at their defaults: the call's kernels are
    the ones named after the choice (``<base>_<option>_<value>``)."""
    half = isinstance(info, index.HalfInfo)
    for option in info.specialized:
        for value in info.option(option).choices:
            call = Call.of(info.name, slipmaps.HUMAN_RUNNER, {option: value}, half=half)
            assert option not in call.values
            for role, spec in info.kernels.items():
                name = call.spec(role).name
                assert name.startswith(spec.base) and f"_{option}_{value.replace('-', '_')}" in name
            choices, default = info.option(option).choices, info.option(option).default
            other = default if value != default else next(c for c in choices if c != value)
            again = Call.of(info.name, slipmaps.HUMAN_RUNNER, {option: other}, half=half)
            assert again.spec(role).name != name


def test_the_call_runs_the_chosen_kernel():
    """The public API's result is the chosen kernel's, called with the index's arguments by name."""
    touchdown = (1.0, -1.2, -0.35, 4.0)
    for value in ("held", "gravity-type0"):
        res = slipmaps.stance("iterative-report", slipmaps.HUMAN_RUNNER, touchdown, zeroth=value)
        call = Call.of("iterative-report", slipmaps.HUMAN_RUNNER, {"zeroth": value})
        spec = call.spec("stance")
        kernel = getattr(importlib.import_module(f"slipmaps.generated.{spec.module}"), spec.name)
        out = np.empty(len(spec.outputs))
        status = kernel(np.array(touchdown), np.array([call.values.get(f, np.nan) for f in spec.p]), out)
        assert res.ok and status == 0
        assert res["t_stance"] == out[spec.outputs.index("t_stance")]


_FIRST_CALL = """
import importlib, json, slipmaps
from slipmaps.runtime.api import index
info = index.get("iterative-report")
slipmaps.apex_return("iterative-report", slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35, zeroth="held")
compiled = {}
for suffix in info.choices.values():
    spec = info.kernels["stance"].chosen(suffix)
    fn = getattr(importlib.import_module(f"slipmaps.generated.{spec.module}"), spec.name)
    compiled[spec.name] = len(fn.signatures)
from slipmaps.generated import geyer
compiled["geyer_stance"] = len(geyer.geyer_stance.signatures)
print(json.dumps(compiled))
"""


def test_a_first_call_compiles_only_its_choice(tmp_path):
    """In a fresh process with an empty numba cache, the first apex return with ``zeroth="held"``
    compiles its stance kernel and no other choice's (nor Geyer et al.'s stance, which only the
    choice "geyer" calls)."""
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    out = subprocess.run(
        [sys.executable, "-c", _FIRST_CALL], env=env, capture_output=True, text=True, check=True
    ).stdout
    compiled = json.loads(out.strip().splitlines()[-1])
    held = [n for n in compiled if n.endswith("_zeroth_held")]
    assert len(held) == 1 and compiled[held[0]] == 1
    assert {n: c for n, c in compiled.items() if n not in held} == dict.fromkeys(set(compiled) - set(held), 0)


def test_specialize_folds_the_switch_and_drops_the_argument():
    """The IR transform: the choice's branch inlined, the option's guard and argument gone."""
    x, k = sym("x"), sym("k")
    kernel = Kernel(
        name="f",
        summary="test",
        equations=(),
        args=(Arg(x, "x"), Arg(k, "k", sp.Or(sp.Eq(k, 0), sp.Eq(k, 1)))),
        steps=(
            Stage((), (Guard(sp.Or(sp.Eq(k, 0), x > 0), "INVALID_INPUT"),)),
            Switch(k, ((0, (Stage(((sym("y"), x + 1),)),)), (1, (Stage(((sym("y"), 2 * x),)),)))),
        ),
        outputs=Group("", (Field("y", "y"),)),
        module="m",
    )
    one = specialize(kernel, {"k": (1, "b")}, {"k": ("a", "b")})
    assert one.name == "f_k_b" and one.arg_names == ("x",)
    assert isinstance(one.steps[1], Stage) and one.steps[1].assignments == ((sym("y"), 2 * x),)
    assert one.steps[0].guards[0].condition == (x > 0)
    zero = specialize(kernel, {"k": (0, "a")}, {"k": ("a", "b")})
    assert zero.steps[0].guards == () and zero.steps[1].assignments == ((sym("y"), x + 1),)
    assert specialize(kernel, {"k": (0, "a")}, {"k": ("a", "b")}) is zero  # cached: one object


def test_only_a_choice_option_can_specialize():
    with pytest.raises(ValueError, match="only a choice option"):
        Option("n", "a number", 1, specialize=True)
    assert not Option("c", "a choice", "a", (("a", ""), ("b", "")), specialize=True).kernel
