"""Layers 1-2 of CODEGEN.md for the kernel IR: ``derive/ir.py`` -> ``derive/lower.py`` -> ``kernels.py.j2``.

Small hand-built kernels (SymPy symbols and the IR classes, nothing from the SLIP derivations) are
lowered, rendered through ``derive.generate.render_kernels`` (the ``kernels.py.j2`` template) as
``derive/generate.py`` renders a module, written into a temporary directory (numba's ``cache=True``
files land next to it) and imported by file path. Two kinds of tests:

- declarations that must be refused at generation time (:class:`LoweringError`, or ``ValueError``
  from the IR constructors): every case is built twice, once correct (it must lower) and once with
  the one defect (it must raise, and the message must name the kernel, the step and the culprit);
- semantics of the compiled code: Stage CSE vs ``sympy.lambdify`` of the same expressions, guards,
  input domains, calls by name, bounded iterations, switches, the batch form vs the scalar form.

Tolerance. A Stage is one ``sympy.cse`` over its assignments (shared temporaries, shared
reciprocals, integer powers); lambdify evaluates the same expressions unshared, so the two differ by
rounding only: measured worst |kernel - lambdify| / max|output| = 8.3e-16 over 3000 points (numpy
2.4, numba 0.68, sympy 1.14). RTOL = 1e-13 keeps two orders of margin and still catches any wrong
term, sign, temporary or reciprocal (O(1) errors). The compiled kernel and its ``.py_func`` (the
same source run by CPython; numba compiles without fastmath) differ by one ulp at about 1 % of the
points (exp, pow and atan2 from LLVM vs CPython's libm): measured worst 6.6e-16 relative to the
largest output; RTOL_PYFUNC = 1e-14.
"""

from __future__ import annotations

import importlib.util
import inspect
import math
import re
import sys

import kernels as kernels_
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from numba.core.registry import CPUDispatcher
from slipmaps.derive import generate
from slipmaps.derive.ir import (
    Arg,
    Call,
    Field,
    Group,
    Guard,
    Iterate,
    Kernel,
    Layout,
    Stage,
    Switch,
    real,
    sym,
)
from slipmaps.derive.lower import LoweringError, lower
from slipmaps.derive.status import STATUS_CODES

STATUS = {name: code for name, code, _ in STATUS_CODES}
OK, INVALID, FALL = STATUS["OK"], STATUS["INVALID_INPUT"], STATUS["FALL"]
NOT_CONVERGED, NUMERICAL_RANGE = STATUS["NOT_CONVERGED"], STATUS["NUMERICAL_RANGE"]
NO_LIFTOFF = STATUS["NO_LIFTOFF"]
NAN, INF = math.nan, math.inf
RTOL = 1e-13
RTOL_PYFUNC = 1e-14
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

x, y, z, w = sym("x"), sym("y"), sym("z"), sym("w")
u, v, r, s = sym("u"), sym("v"), sym("r"), sym("s")
p, q = sym("p"), sym("q")
n_it, tol, x0, c = sym("n"), sym("tol"), sym("x0"), sym("c")
passes = sym("passes")


def _out(*names: str) -> Group:
    return Group("", tuple(Field(nm, nm) for nm in names))


def _args(*symbols: sp.Symbol) -> tuple[Arg, ...]:
    return tuple(Arg(sm, sm.name) for sm in symbols)


def _kernel(name, args, steps, outputs, **kw) -> Kernel:
    return Kernel(
        name=name,
        summary=f"test kernel {name}",
        equations=("test",),
        args=args,
        steps=steps,
        outputs=outputs,
        **kw,
    )


# ----------------------------------------------------------------------------------------------
# Rendering and loading a module of test kernels, the way derive/generate.py does
# ----------------------------------------------------------------------------------------------
def render_module(kernels) -> str:
    return generate.render_kernels(
        [lower(k) for k in kernels],
        source="tests/test_ir.py",
        module_doc="Kernels of tests/test_ir.py.",
        depends=[],
        imports=[],
        status_module="slipmaps.generated.status",
        support_module="slipmaps.generated.support",
    )


def load_module(directory, name: str, kernels):
    """Render ``kernels`` into ``directory/<name>.py`` and import it (numba caches beside it)."""
    path = directory / f"{name}.py"
    path.write_text(render_module(kernels))
    mod_name = f"_slipmaps_test_ir_{name}_{abs(hash(str(directory))):x}"
    spec = importlib.util.spec_from_file_location(mod_name, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[mod_name] = mod
    spec.loader.exec_module(mod)
    return mod


# ----------------------------------------------------------------------------------------------
# Declarations refused at generation time. Each case: make(bad) -> Kernel; make(False) lowers,
# make(True) raises LoweringError whose message contains every fragment.
# ----------------------------------------------------------------------------------------------
def _callee(status: bool = True) -> Kernel:
    """callee(q, p) -> (u = p - 2 q, v = p q + 1[, status]); declared with q first on purpose."""
    return _kernel(
        "callee",
        _args(q, p),
        (Stage(((u, p - 2 * q), (v, p * q + 1)), (Guard(real(u) > 0, "NO_LIFTOFF"),) if status else ()),),
        _out("u", "v"),
        status=status,
        check_inputs=False,
    )


def _bad_stage_symbol(bad):
    return _kernel(
        "k_stage", _args(x), (Stage(((u, x + 1),)), Stage(((v, u + (w if bad else x)),))), _out("v")
    )


def _bad_forward_reference(bad):
    # Within one stage an assignment may use an earlier one, never a later one.
    first, second = ((u, v + 1), (v, x)) if bad else ((v, x), (u, v + 1))
    return _kernel("k_forward", _args(x), (Stage((first, second)),), _out("u", "v"))


def _bad_guard_symbol(bad):
    cond = real(w) > 0 if bad else real(u) > 0
    return _kernel("k_guard", _args(x), (Stage(((u, x),), (Guard(cond, "FALL"),)),), _out("u"))


def _bad_call_argument(bad):
    step = Call(_callee(), {"p": x, "q": w if bad else x}, {"u": "cu"})
    return _kernel("k_call_arg", _args(x), (step,), _out("cu"))


def _bad_iterate_update(bad):
    step = Iterate(((u, x),), (), (u / 2 + (w if bad else x),), n_it, tol, (sp.S.One,), passes)
    return _kernel("k_iter_update", _args(x, n_it, tol), (step,), _out("u"))


def _bad_iterate_body(bad):
    body = (Stage(((s, u + (w if bad else x)),), comment="body stage"),)
    step = Iterate(((u, x),), body, (s / 2,), n_it, tol, (sp.S.One,), passes)
    return _kernel("k_iter_body", _args(x, n_it, tol), (step,), _out("u"))


def _bad_iterate_init(bad):
    step = Iterate(((u, w if bad else x),), (), (u / 2,), n_it, tol, (sp.S.One,), passes)
    return _kernel("k_iter_init", _args(x, n_it, tol), (step,), _out("u"))


def _bad_iterate_bound(bad):
    step = Iterate(((u, x),), (), (u / 2,), w if bad else n_it, tol, (sp.S.One,), passes)
    return _kernel("k_iter_bound", _args(x, n_it, tol), (step,), _out("u"))


def _bad_iterate_scale(bad):
    step = Iterate(((u, x),), (), (u / 2,), n_it, tol, (sp.Abs(w if bad else x) + 1,), passes)
    return _kernel("k_iter_scale", _args(x, n_it, tol), (step,), _out("u"))


def _bad_loop_local_after_loop(bad):
    # After the loop only the state variables and the pass count are visible.
    body = (Stage(((s, u / 2),)),)
    step = Iterate(((u, x),), body, (s,), n_it, tol, (sp.S.One,), passes)
    after = Stage(((v, s if bad else u + passes),))
    return _kernel("k_loop_local", _args(x, n_it, tol), (step, after), _out("v"))


def _bad_switch_selector(bad):
    step = Switch(w if bad else y, ((0, (Stage(((u, x),)),)), (1, (Stage(((u, 2 * x),)),))))
    return _kernel("k_switch_sel", _args(x, y), (step,), _out("u"))


def _bad_switch_branch_symbol(bad):
    step = Switch(y, ((0, (Stage(((u, x),)),)), (1, (Stage(((u, w if bad else x),)),))))
    return _kernel("k_switch_branch", _args(x, y), (step,), _out("u"))


def _bad_private_after_switch(bad):
    # "_t" is private to branch 1: visible after the switch only when every branch defines it.
    b0 = (Stage(((u, x),)),) if bad else (Stage(((sym("_t"), x),)), Stage(((u, sym("_t")),)))
    b1 = (Stage(((sym("_t"), 2 * x),)), Stage(((u, sym("_t")),)))
    return _kernel(
        "k_private", _args(x, y), (Switch(y, ((0, b0), (1, b1))), Stage(((v, sym("_t")),))), _out("v")
    )


def _later_switch(bad_selector: bool, bad_branch: bool):
    # A branch sees what the same branch of an earlier switch on the same selector defined (the
    # tangent code of a loop's switch, run per direction, reads the partials of the values' switch):
    # not another selector's, not another branch's.
    first = Switch(
        y, ((0, (Stage(((u, x),)),)), (1, (Stage(((sym("_t"), 2 * x),)), Stage(((u, sym("_t")),)))))
    )
    reads = (Stage(((v, sym("_t") * x),)),)
    cases = ((0, reads), (1, (Stage(((v, x),)),))) if bad_branch else ((0, (Stage(((v, x),)),)), (1, reads))
    name = "k_later_branch" if bad_branch else "k_later_selector"
    later = Switch(z if bad_selector else y, cases)
    return _kernel(name, _args(x, y, z), (first, later), _out("u", "v"))


def _bad_later_switch_selector(bad):
    return _later_switch(bad, False)


def _bad_later_switch_branch(bad):
    return _later_switch(False, bad)


def _bad_domain_symbol(bad):
    args = (Arg(x, "x", real(w if bad else x) > 0),)
    return _kernel("k_domain", args, (Stage(((u, x),)),), _out("u"))


FREE_SYMBOL_CASES = {
    "stage expression": (_bad_stage_symbol, ["kernel k_stage", "stage 1", "v uses w"]),
    "later name of the same stage": (_bad_forward_reference, ["kernel k_forward", "stage 0", "u uses v"]),
    "guard": (_bad_guard_symbol, ["kernel k_guard", "stage 0", "guard FALL", "uses w"]),
    "call argument": (
        _bad_call_argument,
        ["kernel k_call_arg", "step 0 (call callee)", "argument q", "uses w"],
    ),
    "iterate update": (
        _bad_iterate_update,
        ["kernel k_iter_update", "step 0 (iteration)", "update of u", "w"],
    ),
    "iterate body": (_bad_iterate_body, ["kernel k_iter_body", "stage 0.0 (body stage)", "s uses w"]),
    "iterate initial value": (_bad_iterate_init, ["kernel k_iter_init", "initial value of u", "uses w"]),
    "iterate max_iter": (_bad_iterate_bound, ["kernel k_iter_bound", "max_iter", "uses w"]),
    "iterate scale": (_bad_iterate_scale, ["kernel k_iter_scale", "a scale", "uses w"]),
    "loop-local name after the loop": (
        _bad_loop_local_after_loop,
        ["kernel k_loop_local", "stage 1", "v uses s"],
    ),
    "switch selector": (_bad_switch_selector, ["kernel k_switch_sel", "step 0 (switch on w)", "uses w"]),
    "switch branch": (_bad_switch_branch_symbol, ["kernel k_switch_branch", "stage 0.1.0", "u uses w"]),
    "branch-private name after the switch": (_bad_private_after_switch, ["kernel k_private", "v uses _t"]),
    "branch-private name in another selector's switch": (
        _bad_later_switch_selector,
        ["kernel k_later_selector", "stage 1.1.0", "v uses _t"],
    ),
    "branch-private name in another branch": (
        _bad_later_switch_branch,
        ["kernel k_later_branch", "stage 1.0.0", "v uses _t"],
    ),
    "argument domain": (_bad_domain_symbol, ["kernel k_domain", "domain of argument x", "uses w"]),
}


@pytest.mark.parametrize(("make", "fragments"), FREE_SYMBOL_CASES.values(), ids=FREE_SYMBOL_CASES.keys())
def test_symbol_neither_input_nor_earlier_result_is_rejected(make, fragments):
    lower(make(False))
    with pytest.raises(LoweringError) as err:
        lower(make(True))
    msg = str(err.value)
    assert "neither an input nor the result of an earlier step" in msg
    for frag in fragments:
        assert frag in msg, f"{frag!r} not in {msg!r}"


def _twice_same_stage(bad):
    return _kernel("k_twice", _args(x), (Stage(((u, x), (v if not bad else u, 2 * x))),), _out("u"))


def _twice_two_stages(bad):
    return _kernel("k_twice2", _args(x), (Stage(((u, x),)), Stage((((u if bad else v), 2 * x),))), _out("u"))


def _twice_argument(bad):
    return _kernel("k_twice_arg", _args(x), (Stage((((x if bad else u), 2 * x),)),), _out("x"))


def _twice_call_bind(bad):
    steps = (Stage(((v, x),)), Call(_callee(), {"p": x, "q": x}, {"u": "v" if bad else "cu"}))
    return _kernel("k_twice_call", _args(x), steps, _out("v"))


def _twice_iterate_state(bad):
    step = Iterate((((x if bad else u), x0),), (), (sp.S.Half,), n_it, tol, (sp.S.One,), passes)
    return _kernel("k_twice_state", _args(x0, x, n_it, tol), (step,), _out("x"))


def _twice_iterate_count(bad):
    step = Iterate(((u, x0),), (), (sp.S.Half,), n_it, tol, (sp.S.One,), x if bad else passes)
    return _kernel("k_twice_count", _args(x0, x, n_it, tol), (step,), _out("u"))


def _twice_in_branch(bad):
    steps = (Stage(((v, x),)), Switch(y, ((0, (Stage((((v if bad else u), x),)),)),)))
    return _kernel("k_twice_branch", _args(x, y), steps, _out("v"))


NAME_TWICE_CASES = {
    "same stage": (_twice_same_stage, ["kernel k_twice", "'u' is already defined"]),
    "two stages": (_twice_two_stages, ["kernel k_twice2", "stage 1", "'u' is already defined"]),
    "an argument": (_twice_argument, ["kernel k_twice_arg", "'x' is already defined"]),
    "call binding": (_twice_call_bind, ["kernel k_twice_call", "call callee", "'v' is already defined"]),
    "iterate state": (_twice_iterate_state, ["kernel k_twice_state", "iteration", "'x' is already defined"]),
    "iterate count": (_twice_iterate_count, ["kernel k_twice_count", "iteration", "'x' is already defined"]),
    "switch branch": (_twice_in_branch, ["kernel k_twice_branch", "stage 1.0.0", "'v' is already defined"]),
}


@pytest.mark.parametrize(("make", "fragments"), NAME_TWICE_CASES.values(), ids=NAME_TWICE_CASES.keys())
def test_name_defined_twice_is_rejected(make, fragments):
    lower(make(False))
    with pytest.raises(LoweringError) as err:
        lower(make(True))
    for frag in fragments:
        assert frag in str(err.value), f"{frag!r} not in {str(err.value)!r}"


def _call_missing_arg(bad):
    args = {"p": x} if bad else {"p": x, "q": x}
    return _kernel("k_call_missing", _args(x), (Call(_callee(), args, {"u": "cu"}),), _out("cu"))


def _call_unknown_arg(bad):
    args = {"p": x, "q": x, **({"r": x} if bad else {})}
    return _kernel("k_call_unknown", _args(x), (Call(_callee(), args, {"u": "cu"}),), _out("cu"))


def _call_unknown_output(bad):
    bind = {"u": "cu", **({"t_flight": "ct"} if bad else {})}
    return _kernel("k_call_out", _args(x), (Call(_callee(), {"p": x, "q": x}, bind),), _out("cu"))


def _call_status_into_statusless(bad):
    callee = _callee(status=bad)
    step = Call(callee, {"p": x, "q": x}, {"u": "cu"})
    return _kernel("k_call_status", _args(x), (step,), _out("cu"), status=False, check_inputs=False)


def _switch_different_names(bad):
    b1 = (Stage(((u, 2 * x), *(((v, x),) if bad else ()))),)
    return _kernel(
        "k_switch_names", _args(x, y), (Switch(y, ((0, (Stage(((u, x),)),)), (1, b1))),), _out("u")
    )


def _switch_private_names_may_differ(bad):
    # Names starting with "_" are branch-local helpers: branches may differ in them (control case
    # for the rule above: both variants lower). "bad" renames a public name instead.
    b1 = (Stage(((sym("_h"), 3 * x),)), Stage((((v if bad else u), sym("_h") - x),)))
    return _kernel(
        "k_switch_private", _args(x, y), (Switch(y, ((0, (Stage(((u, x),)),)), (1, b1))),), _out("u")
    )


def _output_never_defined(bad):
    return _kernel("k_output", _args(x), (Stage(((u, x),)),), _out("u", *(("v",) if bad else ())))


def _guard_without_status(bad):
    guards = (Guard(real(x) > 0, "FALL"),) if bad else ()
    return _kernel(
        "k_guard_status", _args(x), (Stage(((u, x),), guards),), _out("u"), status=False, check_inputs=False
    )


def _switch_without_status(bad):
    steps = (Switch(y, ((0, (Stage(((u, x),)),)),)),) if bad else (Stage(((u, x),)),)
    return _kernel("k_switch_status", _args(x, y), steps, _out("u"), status=False, check_inputs=False)


def _iterate_without_status(bad):
    step = Iterate(
        ((u, x),), (), (u / 2,), n_it, tol, (sp.S.One,), passes, fail_status="NOT_CONVERGED" if bad else None
    )
    return _kernel("k_iter_status", _args(x, n_it, tol), (step,), _out("u"), status=False, check_inputs=False)


def _input_checks_without_status(bad):
    return _kernel("k_checks", _args(x), (Stage(((u, x),)),), _out("u"), status=False, check_inputs=bad)


def _layout_without_status(bad):
    return _kernel(
        "k_layout_status",
        _args(y),
        (Stage(((u, y),)),),
        _out("u"),
        status=not bad,
        check_inputs=False,
        layout=Layout(("y",), ()),
    )


def _duplicate_argument(bad):
    return _kernel("k_dup_arg", _args(x, x if bad else y), (Stage(((u, x),)),), _out("u"))


def _duplicate_output(bad):
    return _kernel("k_dup_out", _args(x), (Stage(((u, x),)),), _out("x", "u", *(("u",) if bad else ())))


STRUCTURE_CASES = {
    "call missing argument": (_call_missing_arg, ["kernel k_call_missing", "call callee", "missing ['q']"]),
    "call unknown argument": (_call_unknown_arg, ["kernel k_call_unknown", "call callee", "unknown ['r']"]),
    "call binds unknown output": (_call_unknown_output, ["kernel k_call_out", "no output(s) ['t_flight']"]),
    "call status into status-less": (_call_status_into_statusless, ["kernel k_call_status", "status"]),
    "switch branches define different names": (
        _switch_different_names,
        ["kernel k_switch_names", "branch 1"],
    ),
    "switch public name differs": (_switch_private_names_may_differ, ["kernel k_switch_private", "branch 1"]),
    "output never defined": (_output_never_defined, ["kernel k_output", "['v'] are never defined"]),
    "guard without status": (_guard_without_status, ["kernel k_guard_status", "guard", "no status"]),
    "switch without status": (_switch_without_status, ["kernel k_switch_status", "status"]),
    "failing iteration without status": (_iterate_without_status, ["kernel k_iter_status", "status"]),
    "input checks without status": (_input_checks_without_status, ["kernel k_checks", "status"]),
    "role kernel without status": (_layout_without_status, ["kernel k_layout_status", "status"]),
    "duplicate argument": (_duplicate_argument, ["kernel k_dup_arg", "duplicate argument(s) ['x']"]),
    "duplicate output": (_duplicate_output, ["kernel k_dup_out", "duplicate output(s) ['u']"]),
}


@pytest.mark.parametrize(("make", "fragments"), STRUCTURE_CASES.values(), ids=STRUCTURE_CASES.keys())
def test_inconsistent_declaration_is_rejected(make, fragments):
    lower(make(False))
    with pytest.raises(LoweringError) as err:
        lower(make(True))
    for frag in fragments:
        assert frag in str(err.value), f"{frag!r} not in {str(err.value)!r}"


def test_guard_refuses_condition_folded_by_assumptions():
    """A positive=True symbol makes ``m > 0`` fold to True: the run-time check would vanish."""
    m_pos = sp.Symbol("m", positive=True)
    assert (m_pos > 0) is sp.true
    with pytest.raises(ValueError, match="folds to the constant True"):
        Guard(m_pos > 0, "FALL")
    with pytest.raises(ValueError, match="folds to the constant False"):
        Guard(m_pos < 0, "FALL")
    g = Guard(real(m_pos) > 0, "FALL")  # the same condition on the assumption-free symbol survives
    assert g.condition.free_symbols == {real(m_pos)}
    with pytest.raises(ValueError, match="unknown status"):
        Guard(real(m_pos) > 0, "NO_SUCH_STATUS")


def test_iterate_needs_one_update_and_scale_per_state_variable():
    with pytest.raises(ValueError, match="one update expression and one scale"):
        Iterate(((u, x), (v, x)), (), (u,), n_it, tol, (sp.S.One, sp.S.One), passes)
    with pytest.raises(ValueError, match="unknown status"):
        Iterate(((u, x),), (), (u,), n_it, tol, (sp.S.One,), passes, fail_status="NOPE")


def test_layout_holds_exactly_the_arguments():
    """A role kernel's layout reads every argument from x or p, and x holds arguments only."""
    with pytest.raises(ValueError, match=r"kernel k_layout: .*missing \['y'\]"):
        _kernel("k_layout", _args(x, y), (Stage(((u, x + y),)),), _out("u"), layout=Layout(("x",), ()))
    with pytest.raises(ValueError, match=r"kernel k_layout: .*not \['z'\]"):
        _kernel("k_layout", _args(x), (Stage(((u, x),)),), _out("u"), layout=Layout(("x", "z"), ()))
    with pytest.raises(ValueError, match="names a field twice"):
        Layout(("x", "x"), ())


def test_argument_domain_folded_by_assumptions_is_refused():
    """A domain SymPy folds to True through the symbol's assumptions would never be checked."""
    m_pos = sp.Symbol("m", positive=True)
    with pytest.raises(ValueError, match="domain of argument m folds"):
        Arg(m_pos, "m", m_pos > 0)


@pytest.mark.parametrize(
    "name",
    ["_x0", "_c3", "_it0", "_n0_1", "_conv2", "_a1", "_o3", "_p2", "_code", "STATUS_OK", "out", "i", "stack"],
)
def test_names_of_the_generated_code_are_reserved(name):
    """A local named like a CSE temporary (``_x0``) would be overwritten by a later stage's temporary
    (a wrong value, no error): every name the lowering or the template uses is refused."""
    steps = (
        Stage(((sym(name), 2 * x),)),
        Stage(((u, sp.sin(x * y) + sp.cos(x * y)),)),
        Stage(((v, sym(name)),)),
    )
    with pytest.raises(LoweringError, match="reserved for the generated code"):
        lower(_kernel("k_temp_clash", _args(x, y), steps, _out("u", "v")))


def test_keyword_symbol_name_is_refused():
    """A symbol named like a Python keyword ("lambda", as derive/symbols.py's lam) would print as
    ``lambda_`` where used but ``lambda`` where assigned: a SyntaxError in the rendered module."""
    lam = sp.Symbol("lambda", real=True)
    kern = _kernel("k_keyword", _args(x), (Stage(((lam, 2 * x),)), Stage(((u, lam + 1),))), _out("u"))
    with pytest.raises(LoweringError, match="not a valid Python identifier"):
        lower(kern)


# ----------------------------------------------------------------------------------------------
# Semantics of compiled kernels: one module of small kernels, compiled once
# ----------------------------------------------------------------------------------------------
#: One stage per list: (name, expression). Shared subexpressions across outputs, reciprocals of an
#: input and of a temporary used several times, 1/sqrt, negative and rational powers, a later
#: assignment using an earlier one of the same stage and of an earlier stage, Abs, Piecewise, min.
_xy = x * y
CSE_STAGES = [
    [
        (u, sp.sin(_xy) + _xy**2 / z + 1 / z**2),
        (v, u * sp.exp(-_xy / 4) + 1 / z + 1 / _xy + 3 / _xy**2),
        (r, sp.sqrt(x**2 + y**2 + 1)),
        (sym("h"), 1 / sp.sqrt(x**2 + y**2 + 1) + u / r),
    ],
    [
        (s, u * v / r + r**-3 + sp.Rational(2, 7) * sym("h")),
        (sym("o1"), sp.cos(u - v) ** 3 / (1 + r) + s),
        (sym("o2"), sp.log(1 + x**2) * v - sp.Abs(u - 2) + (x * z) ** sp.Rational(3, 2)),
        (sym("o3"), sp.Piecewise((u**2, u > v), (v - u, True)) + sp.Min(x, y) * sp.atan2(y, -z)),
    ],
]
CSE_OUTPUTS = ("u", "v", "r", "h", "s", "o1", "o2", "o3")


def _cse_kernel():
    return _kernel(
        "cse_stages",
        _args(x, y, z),
        tuple(Stage(tuple(stage)) for stage in CSE_STAGES),
        _out(*CSE_OUTPUTS),
        status=False,
        check_inputs=False,
    )


def _guarded_steps():
    d, big = sym("d"), sym("big")
    return (
        Stage(
            ((d, x - y),),
            (
                Guard(real(d) > 0, "FALL", "d > 0"),
                Guard(real(d) < 1e6, "NO_LIFTOFF", "d < 1e6 (checked after the first guard)"),
            ),
        ),
        Stage(((r, sp.sqrt(d)), (big, r * y))),
    )


def _guarded(check: bool):
    args = (Arg(x, "x", real(x) > -100), Arg(y, "y", real(y) > 0)) if check else _args(x, y)
    name = "guarded" if check else "guarded_unchecked"
    return _kernel(name, args, _guarded_steps(), _out("r", "big"), check_inputs=check)


def _plain_callee():
    return _kernel("triple", _args(p), (Stage(((w, 3 * p),)),), _out("w"), status=False, check_inputs=False)


def _caller():
    return _kernel(
        "caller",
        _args(x, y),
        (
            Call(_callee(), {"p": x, "q": y}, {"v": "cv", "u": "cu"}, comment="callee(q=y, p=x)"),
            Call(_plain_callee(), {"p": sym("cu")}, {"w": "cw"}),
        ),
        _out("cu", "cv", "cw"),
    )


def _fixed_cos():
    step = Iterate(((u, x0),), (), (sp.cos(u),), n_it, tol, (sp.S.One,), passes, comment="u <- cos(u)")
    args = (Arg(x0, "x0"), Arg(n_it, "n", real(n_it) >= 0), Arg(tol, "tol", real(tol) >= 0))
    return _kernel("fixed_cos", args, (step,), _out("u", "passes"))


def _affine():
    """u <- a u + c with the scale sc: contracting |a| < 1, divergent |a| > 1, oscillating a = -1."""
    a_, sc = sym("a"), sym("sc")
    step = Iterate(((u, x0),), (), (a_ * u + c,), n_it, tol, (sc,), passes)
    args = (
        Arg(x0, "x0"),
        Arg(a_, "a"),
        Arg(c, "c"),
        Arg(sc, "sc", real(sc) > 0),
        Arg(n_it, "n"),
        Arg(tol, "tol"),
    )
    return _kernel("affine", args, (step,), _out("u", "passes"), check_inputs=True)


def _constant_update():
    """u <- c (c may be NaN: no input checks); fail_status None: no NOT_CONVERGED."""
    step = Iterate(((u, x0),), (), (c,), n_it, tol, (sp.S.One,), passes)
    return _kernel(
        "constant_update", _args(x0, c, n_it, tol), (step,), _out("u", "passes"), check_inputs=False
    )


def _swap():
    """(u, v) <- (v, u): the updates are simultaneous (a sequential update would give (v, v))."""
    step = Iterate(
        ((u, x), (v, y)), (), (v, u), n_it, sp.S.Zero, (sp.S.One, sp.S.One), passes, fail_status=None
    )
    return _kernel("swap", _args(x, y, n_it), (step,), _out("u", "v", "passes"))


def _newton():
    """Newton's iteration for sqrt(c) with a body stage: u <- u - f/f'."""
    f, fp = sym("f"), sym("fp")
    body = (Stage(((f, u**2 - c), (fp, 2 * u)), (Guard(real(fp) > 0, "FALL", "u stays positive"),)),)
    step = Iterate(((u, x0),), body, (u - f / fp,), n_it, tol, (sp.Abs(c) + 1,), passes)
    return _kernel("newton", _args(x0, c, n_it, tol), (step,), _out("u", "passes"))


def _switch():
    t_ = sym("_t")
    cases = (
        (0, (Stage(((u, x + 1),)),)),
        (1, (Stage(((t_, 3 * x),)), Stage(((u, t_ - x),)))),  # 2 x through a branch-private name
        (5, (Stage(((u, x**2),), (Guard(real(x) > 0, "FALL"),)),)),
    )
    return _kernel(
        "switch",
        _args(x, y),
        (Switch(y, cases, comment="by option y"), Stage(((v, u + 0.5),))),
        _out("u", "v"),
    )


def _switch_in_loop():
    """u <- u/2 (option 0) or triple(u)/9 = u/3 (option 1), through a Switch and a Call in the body."""
    cases = (
        (0, (Stage(((s, u / 2),)),)),
        (1, (Call(_plain_callee(), {"p": u}, {"w": "_w3"}), Stage(((s, sym("_w3") / 9),)))),
    )
    step = Iterate(
        ((u, x),), (Switch(y, cases),), (s,), n_it, sp.S.Zero, (sp.S.One,), passes, fail_status=None
    )
    return _kernel("switch_in_loop", _args(x, y, n_it), (step,), _out("u", "passes"))


def _batched():
    """Rows a, y; parameter k. Domain y > 0; guard a > y; one NaN-producing output scale (a role
    kernel: its inputs are not named x or p, its layouts' names)."""
    k_, a = sym("k"), sym("a")
    args = (Arg(a, "a"), Arg(k_, "k", real(k_) > 0), Arg(y, "y", real(y) > 0))
    steps = (
        Stage(((sym("d"), a - y),), (Guard(real(sym("d")) > 0, "FALL"),)),
        Stage(((r, k_ * sp.sqrt(sym("d"))), (s, a / y + sp.log(k_)))),
    )
    return _kernel("batched", args, steps, _out("r", "s"), layout=Layout(("a", "y"), ("k",)))


def _row(fn, xv, k_, yv) -> tuple:
    """The role kernel ``batched`` at one point: (r, s, status)."""
    out = np.empty(2)
    status = fn(np.array([xv, yv], dtype=float), np.array([k_], dtype=float), out)
    return (*map(float, out), int(status))


def _all_kernels():
    return [
        _cse_kernel(),
        _guarded(True),
        _guarded(False),
        _callee(),
        _plain_callee(),
        _caller(),
        _fixed_cos(),
        _affine(),
        _constant_update(),
        _swap(),
        _newton(),
        _switch(),
        _switch_in_loop(),
        _batched(),
    ]


@pytest.fixture(scope="module")
def gen(tmp_path_factory):
    return load_module(tmp_path_factory.mktemp("ir_kernels"), "ir_kernels", _all_kernels())


def _py_reference_stages(point: dict) -> dict:
    """The stages evaluated assignment by assignment with sympy.lambdify (no CSE)."""
    env = dict(point)
    for stage in CSE_STAGES:
        for name, expr in stage:
            syms = sorted(expr.free_symbols, key=lambda sm: sm.name)
            fn = sp.lambdify(syms, expr, modules="math")
            env[name.name] = float(fn(*(env[sm.name] for sm in syms)))
    return env


@SETTINGS
@given(
    st.floats(0.2, 3.0),
    st.floats(0.2, 3.0),
    st.floats(0.2, 3.0),
)
def test_stage_cse_matches_lambdify(gen, xv, yv, zv):
    got = gen.cse_stages(xv, yv, zv)
    ref = _py_reference_stages({"x": xv, "y": yv, "z": zv})
    expected = np.array([ref[nm] for nm in CSE_OUTPUTS])
    np.testing.assert_allclose(got, expected, rtol=RTOL, atol=RTOL * np.abs(expected).max())
    scale = np.abs(expected).max()
    np.testing.assert_allclose(gen.cse_stages.py_func(xv, yv, zv), got, rtol=0, atol=RTOL_PYFUNC * scale)


def test_stage_cse_shares_temporaries_and_reciprocals():
    """The lowering does share: one 1/z for all its uses, CSE temporaries numbered _x<N>."""
    src = render_module([_cse_kernel()])
    body = src.split("def cse_stages", 1)[1]
    assert body.count("1.0/z") == 1, body
    assert len([ln for ln in body.splitlines() if ln.strip().startswith("_x")]) >= 4


def test_guard_failure_gives_nan_outputs_and_its_status(gen):
    assert gen.guarded(5.0, 1.0) == (2.0, 2.0, OK)
    for kern in (gen.guarded, gen.guarded_unchecked):
        for args, status in (
            ((0.5, 1.0), FALL),
            ((1.0, 1.0), FALL),
            ((2e6, 1.0), NO_LIFTOFF),
            ((-50, 1), FALL),
        ):
            res = kern(*map(float, args))
            assert res[-1] == status, (kern, args, res)
            assert all(math.isnan(val) for val in res[:-1])


def test_guard_fails_on_nan(gen):
    """NaN reaching a guard fails it (with the guard's own status when inputs are not checked)."""
    for args in ((NAN, 1.0), (1.0, NAN)):
        res = gen.guarded_unchecked(*args)
        assert res[-1] == FALL and all(math.isnan(val) for val in res[:-1]), res


def test_input_domain_violations_give_invalid_input(gen):
    for args in ((NAN, 1.0), (5.0, NAN), (INF, 1.0), (5.0, -INF), (5.0, 0.0), (5.0, -1.0), (-100.0, 1.0)):
        res = gen.guarded(*args)
        assert res[-1] == INVALID and all(math.isnan(val) for val in res[:-1]), (args, res)
    # The domains are strict inequalities, checked exactly at their edges.
    assert gen.guarded(5.0, 5e-324)[-1] == OK
    assert gen.guarded(math.nextafter(-100.0, 0.0), 1.0)[-1] == FALL  # inside the domain, fails the guard


def test_nonfinite_output_gives_numerical_range(gen):
    """The final all-finite check: x / y overflows although every guard passed."""
    res = _row(gen.batched, 1e308, 2.0, 1e-10)
    assert res[-1] == NUMERICAL_RANGE and all(math.isnan(val) for val in res[:-1]), res
    assert _row(gen.batched, 1e300, 2.0, 1e-5)[-1] == OK


def test_call_passes_arguments_by_name(gen):
    """callee is declared (q, p); the caller maps p = x, q = y: u = x - 2 y, v = x y + 1, w = 3 u."""
    assert list(inspect.signature(gen.callee.py_func).parameters) == ["q", "p"]
    assert gen.callee(1.0, 5.0) == (3.0, 6.0, OK)
    assert gen.caller(5.0, 1.0) == (3.0, 6.0, 9.0, OK)
    assert gen.caller(7.0, 2.0) == (3.0, 15.0, 9.0, OK)


def test_call_propagates_callee_status(gen):
    res = gen.caller(1.0, 1.0)  # u = -1: the callee's guard fails with NO_LIFTOFF
    assert res[-1] == NO_LIFTOFF and all(math.isnan(val) for val in res[:-1]), res
    res = gen.caller(NAN, 1.0)  # the caller's input check comes first
    assert res[-1] == INVALID


def _iterate_reference(update, x_init, max_iter, tol_, scale):
    """The documented Iterate semantics in plain Python: (state, passes, converged)."""
    val, count, conv = x_init, 0, False
    for _ in range(int(max_iter)):
        new = update(val)
        conv = abs(new - val) <= tol_ * scale
        val, count = new, count + 1
        if conv:
            break
    return val, count, conv


@pytest.mark.parametrize("tol_", [1e-3, 1e-9, 1e-14])
@pytest.mark.parametrize("start", [0.0, 1.0, -3.0, 100.0])
def test_iterate_contraction_converges_with_pass_count(gen, start, tol_):
    val, count, conv = _iterate_reference(math.cos, start, 1000, tol_, 1.0)
    assert conv
    got = gen.fixed_cos(start, 1000.0, tol_)
    assert got[2] == OK
    assert got[1] == count  # the number of passes, including the last (converged) one
    assert got[0] == pytest.approx(val, rel=1e-15, abs=0)
    # the next step of a contraction is shorter than the last (<= tol): the result is near the fixed point
    assert abs(math.cos(got[0]) - got[0]) <= tol_ + 1e-16


def test_iterate_newton_body_and_scale(gen):
    for cv, start in ((2.0, 1.0), (1e4, 3.0), (0.25, 5.0)):
        val, count, conv = _iterate_reference(
            lambda xx, cv=cv: xx - (xx * xx - cv) / (2 * xx), start, 50, 1e-12, abs(cv) + 1
        )
        got = gen.newton(start, cv, 50.0, 1e-12)
        assert conv and got[2] == OK
        assert (got[0], got[1]) == (pytest.approx(math.sqrt(cv), rel=1e-15), count)
    res = gen.newton(-1.0, 2.0, 50.0, 1e-12)  # the body's guard fails on the first pass
    assert res[-1] == FALL and math.isnan(res[0])


@pytest.mark.parametrize("max_iter", [1, 2, 7, 40])
def test_iterate_tol_zero_runs_exactly_max_iter_passes(gen, max_iter):
    expected = 0.3
    for _ in range(max_iter):
        expected = math.cos(expected)
    got = gen.fixed_cos(0.3, float(max_iter), 0.0)
    assert got == (pytest.approx(expected, rel=1e-15), float(max_iter), OK)


def test_iterate_tol_zero_runs_all_passes_even_at_an_exact_fixed_point(gen):
    assert gen.constant_update(1.0, 2.0, 5.0, 0.0)[:2] == (2.0, 5.0)  # u <- 2: still moving after pass 1
    assert gen.fixed_cos(0.3, 500.0, 0.0)[1] == 500.0  # cos reaches its float fixed point after ~93 passes


@pytest.mark.parametrize(
    ("a_", "c_", "start"),
    [(2.0, 1.0, 1.0), (-1.0, 0.0, 1.0), (-1.5, 0.0, 1e-3), (1.0, 0.5, 0.0)],
    ids=["divergent", "oscillating", "divergent-oscillating", "drifting"],
)
def test_iterate_not_converging_gives_not_converged(gen, a_, c_, start):
    res = gen.affine(start, a_, c_, 1.0, 60.0, 1e-6)
    assert res[-1] == NOT_CONVERGED and all(math.isnan(val) for val in res[:-1]), res
    # the same iteration with tol = 0 is a bounded run, not a failure
    val, count, _ = _iterate_reference(lambda xx: a_ * xx + c_, start, 60, 0.0, 1.0)
    assert gen.affine(start, a_, c_, 1.0, 60.0, 0.0) == (val, float(count), OK)


def test_iterate_convergence_uses_the_scale(gen):
    """|du| <= tol * sc: u <- u/2 from 1 stops when 2^-k <= tol * sc."""
    for sc, tol_ in ((1.0, 1e-3), (1e3, 1e-3), (1e-3, 1e-3), (5.0, 0.5)):
        val, count, conv = _iterate_reference(lambda xx: 0.5 * xx, 1.0, 200, tol_, sc)
        assert conv
        assert gen.affine(1.0, 0.5, 0.0, sc, 200.0, tol_) == (val, float(count), OK)


def test_iterate_nan_update_never_converges(gen):
    res = gen.constant_update(1.0, NAN, 20.0, 1e-3)  # u <- NaN
    assert res[-1] == NOT_CONVERGED and all(math.isnan(val) for val in res[:-1]), res
    res = gen.constant_update(1.0, NAN, 20.0, INF)  # even an infinite tolerance does not accept NaN
    assert res[-1] == NOT_CONVERGED
    assert gen.constant_update(1.0, 2.0, 20.0, 1e-3) == (2.0, 2.0, OK)  # control: u <- 2 converges on pass 2


def test_iterate_max_iter_zero_leaves_the_initial_value(gen):
    assert gen.fixed_cos(0.3, 0.0, 0.0) == (0.3, 0.0, OK)
    assert gen.swap(1.0, 2.0, 0.0) == (1.0, 2.0, 0.0, OK)


def test_iterate_updates_are_simultaneous(gen):
    assert gen.swap(1.0, 2.0, 1.0) == (2.0, 1.0, 1.0, OK)
    assert gen.swap(1.0, 2.0, 2.0) == (1.0, 2.0, 2.0, OK)
    assert gen.swap(1.0, 2.0, 7.0) == (2.0, 1.0, 7.0, OK)


def test_switch_in_iterate_body_with_call(gen):
    assert gen.switch_in_loop(64.0, 0.0, 3.0) == (8.0, 3.0, OK)
    assert gen.switch_in_loop(81.0, 1.0, 2.0) == (pytest.approx(9.0, rel=1e-15), 2.0, OK)
    assert gen.switch_in_loop(81.0, 2.0, 2.0)[-1] == INVALID  # unknown code inside the loop


def test_switch_picks_the_branch_by_code(gen):
    assert gen.switch(3.0, 0.0) == (4.0, 4.5, OK)
    assert gen.switch(3.0, 1.0) == (6.0, 6.5, OK)
    assert gen.switch(3.0, 5.0) == (9.0, 9.5, OK)
    res = gen.switch(-3.0, 5.0)  # a guard inside the branch
    assert res[-1] == FALL and all(math.isnan(val) for val in res[:-1])


@pytest.mark.parametrize("code", [2.0, 3.0, 4.0, 6.0, -1.0, 0.5, 1.0 + 1e-15, 1e300, 1e-300])
def test_switch_unknown_code_gives_invalid_input(gen, code):
    res = gen.switch(3.0, code)
    assert res[-1] == INVALID and all(math.isnan(val) for val in res[:-1]), res


def test_switch_negative_zero_is_code_zero(gen):
    assert gen.switch(3.0, -0.0) == (4.0, 4.5, OK)


def _batch_rows():
    """Rows: good ones, a guard failure, domain violations, NaN / inf inputs, an overflow."""
    xs = [3.0, 10.0, 0.5, 2.0, NAN, 5.0, INF, 1e308, 7.0, 4.0, 2.5, 9.0]
    ys = [1.0, 2.0, 1.0, 0.0, 1.0, NAN, 1.0, 1e-10, -1.0, 3.9, 2.5, 0.1]
    return xs, ys


@pytest.mark.parametrize("k_", [2.0, 0.5, -1.0, NAN])
def test_batch_equals_scalar_bit_for_bit(gen, k_):
    xs, ys = _batch_rows()
    n = len(xs)
    X = np.ascontiguousarray(np.column_stack([xs, ys]))
    OUT = np.full((n, 2), -123.0)
    STATUS = np.full(n, -1, dtype=np.int64)
    gen.batched_rows(X, np.array([[k_]]), OUT, STATUS)
    ref = [_row(gen.batched, xv, k_, yv) for xv, yv in zip(xs, ys, strict=True)]
    np.testing.assert_array_equal(OUT, np.array([rr[:2] for rr in ref]))
    np.testing.assert_array_equal(STATUS, [rr[2] for rr in ref])
    statuses = set(STATUS.tolist())
    if math.isfinite(k_) and k_ > 0:
        assert {OK, FALL, INVALID, NUMERICAL_RANGE} <= statuses  # the rows exercise every path
    else:
        assert statuses == {INVALID}  # a bad parameter invalidates every row


def test_batch_takes_a_parameter_record_per_row(gen):
    """P of one row serves every row; P of n rows gives row i its own record."""
    xs, ys = _batch_rows()
    n = len(xs)
    X = np.ascontiguousarray(np.column_stack([xs, ys]))
    ks = np.linspace(0.5, 3.0, n)
    OUT, STATUS = np.empty((n, 2)), np.empty(n, dtype=np.int64)
    gen.batched_rows(X, ks[:, None].copy(), OUT, STATUS)
    for i in range(n):
        ref = _row(gen.batched, xs[i], ks[i], ys[i])
        np.testing.assert_array_equal(OUT[i], ref[:2])
        assert STATUS[i] == ref[2]


@SETTINGS
@given(
    st.lists(
        st.tuples(
            st.one_of(st.floats(-10, 10), st.sampled_from([NAN, INF, -INF])),
            st.one_of(st.floats(-1, 10), st.sampled_from([NAN, INF, 0.0])),
        ),
        min_size=1,
        max_size=20,
    ),
    st.floats(0.1, 10),
)
def test_batch_equals_scalar_property(gen, rows, k_):
    X = np.array(rows, dtype=float).reshape(-1, 2)
    OUT = np.empty((len(rows), 2))
    STATUS = np.empty(len(rows), dtype=np.int64)
    gen.batched_rows(X, np.array([[k_]]), OUT, STATUS)
    for i, (xv, yv) in enumerate(rows):
        ref = _row(gen.batched, xv, k_, yv)
        np.testing.assert_array_equal(OUT[i], ref[:2])
        assert STATUS[i] == ref[2]


def test_role_kernel_signature_is_its_layouts(gen):
    assert list(inspect.signature(gen.batched.py_func).parameters) == ["x", "p", "out"]
    assert list(inspect.signature(gen.batched_rows.py_func).parameters) == ["X", "P", "OUT", "STATUS"]


def test_every_function_is_a_numba_dispatcher_and_compiles(gen):
    """No silent pure-Python fallback: every function the module defines is jitted and compiles."""
    kernels = _all_kernels()
    names = {k.name for k in kernels} | {f"{k.name}_rows" for k in kernels if k.layout}
    plain = [
        nm for nm, obj in vars(gen).items() if inspect.isfunction(obj) and obj.__module__ == gen.__name__
    ]
    assert plain == []
    own = {
        nm
        for nm, obj in vars(gen).items()
        if isinstance(obj, CPUDispatcher) and obj.__module__ == gen.__name__
    }
    assert own == names  # (and the support module's functions it imports)
    text = render_module(kernels)
    decorators = re.findall(r"^@(.*)\ndef (\w+)\(", text, re.MULTILINE)
    assert sorted(nm for _, nm in decorators) == sorted(re.findall(r"^def (\w+)\(", text, re.MULTILINE))
    for deco, nm in decorators:
        assert deco.startswith("njit(cache=True") and "fastmath" not in deco, (nm, deco)
        assert "parallel=True" not in deco, (nm, deco)  # the runtime spreads batches over threads
        assert ("nogil=True" in deco) == nm.endswith("_rows"), (nm, deco)
    # Compile every kernel in nopython mode, whatever its convention: a signature is produced.
    for kern in kernels:
        disp = getattr(gen, kern.name)
        kernels_.invoke(kern, dict.fromkeys(kern.arg_names, 1.0), disp)
        assert disp.signatures, kern.name


# ----------------------------------------------------------------------------------------------
# The status codes: imported from generated/status.py, not copied into each module
# ----------------------------------------------------------------------------------------------
def test_status_codes_are_imported_not_copied(gen):
    from slipmaps.generated import status as g_status

    text = render_module(_all_kernels())
    assert not re.search(r"^STATUS_\w+ = ", text, re.MULTILINE)
    (line,) = re.findall(r"^from slipmaps\.generated\.status import .*$", text, re.MULTILINE)
    names = set(re.findall(r"STATUS_(\w+)", line))
    # exactly the codes the kernels name, with the values of derive/status.py
    assert names == set(re.findall(r"\bSTATUS_(\w+)\b", text.replace(line, "")))
    assert all(
        getattr(gen, f"STATUS_{nm}") == STATUS[nm] == getattr(g_status, f"STATUS_{nm}") for nm in names
    )
    assert gen.guarded(0.5, 1.0)[-1] == g_status.STATUS_FALL


# ----------------------------------------------------------------------------------------------
# Jacobians in one pass (derive/tangent.py): synthetic kernels against central differences
# ----------------------------------------------------------------------------------------------
a_, b_, k_, m_, t_ = sym("a"), sym("b"), sym("k"), sym("m"), sym("t")


def _d_stages():
    """Stages: shared subexpressions, a later assignment using earlier ones, a guard, Abs and a
    Piecewise (almost-everywhere derivatives), an output identically independent of b."""
    steps = (
        Stage(((u, sp.sin(a_ * b_) + sp.exp(-(a_**2)) / b_), (v, u**2 * sp.sqrt(b_) + sp.Abs(a_ - 3)))),
        Stage(
            ((w, sp.Piecewise((v * a_, a_ > 1), (v + a_, True)) + sp.atan2(b_, 2)),),
            (Guard(real(b_) > 0, "FALL"),),
        ),
        Stage(((r, 7 * a_**3),)),
    )
    return _kernel("d_stages", _args(a_, b_), steps, _out("u", "v", "w", "r"))


def _d_inner():
    """A callee with more active arguments than its caller has directions (a vector JVP)."""
    steps = (Stage(((u, p * sp.cos(q) + x * y), (v, sp.exp(p - q) * y / (1 + x**2)))),)
    return _kernel("d_inner", _args(p, q, x, y), steps, _out("u", "v"))


def _d_small():
    """A callee with fewer active arguments than its caller's directions (its own Jacobian)."""
    steps = (Stage(((w, sp.log(1 + p**2) * q),), (Guard(real(q) > -10, "NO_LIFTOFF"),)),)
    return _kernel("d_small", _args(p, q, m_), steps, _out("w"))


def _d_calls():
    steps = (
        Call(_d_inner(), {"p": a_, "q": 2 * b_, "x": a_ * b_, "y": sp.sin(a_)}, {"u": "iu", "v": "iv"}),
        Call(_d_small(), {"p": sym("iu"), "q": sym("iv"), "m": sp.Float(3.0)}, {"w": "sw"}),
        Stage(((r, sym("sw") * a_ + sym("iv")),)),
    )
    return _kernel("d_calls", _args(a_, b_), steps, _out("iu", "iv", "sw", "r"))


def _d_loop(evaluate: bool):
    """u <- u - (u^3 - a u - b) / (3 u^2 - a) (Newton, tol > 0) with a value evaluated at every
    iterate (``evaluate``) or in the body; iterations as an argument (0: the start value)."""
    f, fp = sym("f"), sym("fp")
    ev = (Stage(((f, u**3 - a_ * u - b_), (fp, 3 * u**2 - a_)), (Guard(real(fp) > 0, "FALL"),)),)
    step = Iterate(
        ((u, 1 + b_ / 4),),
        () if evaluate else ev,
        (u - f / fp,),
        n_it,
        tol,
        (sp.S.One,),
        passes,
        evaluate=ev if evaluate else (),
    )
    after = (Stage(((v, u * a_ + (f if evaluate else 0)),)),)
    name = "d_loop_evaluate" if evaluate else "d_loop_body"
    return _kernel(name, _args(a_, b_, n_it, tol), (step,) + after, _out("u", "v", "passes"))


def _d_picard():
    """A contraction with tol = 0 (exactly n passes) whose state is two variables."""
    step = Iterate(
        ((u, a_), (v, b_)),
        (),
        (sp.cos(v) / 2 + a_ / 3, sp.sin(u) * b_ / 3 + 1),
        n_it,
        sp.S.Zero,
        (sp.S.One, sp.S.One),
        passes,
        fail_status=None,
        evaluate=(Stage(((w, u * v),)),),
    )
    return _kernel("d_picard", _args(a_, b_, n_it), (step, Stage(((r, w + u),))), _out("u", "v", "w", "r"))


def _d_tail():
    """A loop that reads only a, then a tail (stages right after it, differentiated per direction
    with the loop) that reads b too."""
    step = Iterate(
        ((u, a_),), (), (sp.cos(u) / 2 + a_ / 3,), n_it, sp.S.Zero, (sp.S.One,), passes, fail_status=None
    )
    tail = (Stage(((v, u * b_ + b_**2),)), Stage(((w, sp.exp(v) * a_),)))
    return _kernel("d_tail", _args(a_, b_, n_it), (step, *tail), _out("u", "v", "w"))


def _d_loop_switch():
    """A loop whose evaluation and body branch on an option, a call in a branch, a switch after it."""
    h_, g_ = sym("h"), sym("g")
    evaluate = (
        Switch(
            k_,
            (
                (0, (Stage(((h_, sp.sin(u) * a_ + b_),)),)),
                (1, (Stage(((sym("_e"), sp.exp(-u * b_)),)), Stage(((h_, sym("_e") * a_ + u**2 / 3),)))),
            ),
        ),
    )
    body = (
        Switch(
            k_,
            (
                (0, (Stage(((g_, h_ / 2 + u / 4),)),)),
                (
                    1,
                    (
                        Call(_d_small(), {"p": h_, "q": b_, "m": a_}, {"w": "_sw"}),
                        Stage(((g_, sym("_sw") / 3 + u / 5),)),
                    ),
                ),
            ),
        ),
    )
    step = Iterate(
        ((u, b_ / 2),), body, (g_,), n_it, sp.S.Zero, (sp.S.One,), passes, fail_status=None, evaluate=evaluate
    )
    tail = (Switch(k_, ((0, (Stage(((v, h_ * b_),)),)), (1, (Stage(((v, h_ + a_),)),)))),)
    return _kernel("d_loop_switch", _args(a_, b_, k_, n_it), (step, *tail), _out("u", "h", "v"))


def _d_switch():
    """Branches defining the same outputs differently, one of them through a call and a loop."""
    s_, count = sym("_s"), sym("_count")
    inner = Iterate(
        ((s_, a_),), (), (sp.sqrt(s_ + b_ * b_),), n_it, sp.S.Zero, (sp.S.One,), count, fail_status=None
    )
    cases = (
        (
            0,
            (
                Stage(
                    ((u, a_ * b_), (v, sp.S(2))),
                ),
            ),
        ),
        (
            1,
            (
                Call(_d_inner(), {"p": a_, "q": b_, "x": b_, "y": a_}, {"u": "u", "v": "_iv"}),
                Stage(((v, sym("_iv") + a_),)),
            ),
        ),
        (2, (inner, Stage(((u, s_), (v, s_ * a_))))),
    )
    return _kernel(
        "d_switch", _args(a_, b_, k_, n_it), (Switch(k_, cases), Stage(((w, u * v),))), _out("u", "v", "w")
    )


def _d_nested():
    """A loop in a loop: the outer one runs the inner Picard loop from its current state."""
    inner = Iterate(
        ((s, u),),
        (),
        (sp.cos(s) * a_ / 2 + u / 4,),
        n_it,
        sp.S.Zero,
        (sp.S.One,),
        sym("_ip"),
        fail_status=None,
    )
    outer = Iterate(
        ((u, b_),),
        (inner,),
        (s * b_ / 2 + sp.sin(u) / 5,),
        sym("n2"),
        sp.S.Zero,
        (sp.S.One,),
        passes,
        fail_status=None,
    )
    return _kernel("d_nested", _args(a_, b_, n_it, sym("n2")), (outer,), _out("u", "passes"))


#: kernel, the arguments to differentiate with respect to, points (argument values), steps h
D_CASES = {
    "d_stages": (_d_stages, ("a", "b"), [(0.7, 1.3), (2.5, 0.4)]),
    "d_calls": (_d_calls, ("a", "b"), [(0.7, 1.3), (1.1, -0.4)]),
    "d_loop_evaluate": (
        _d_loop,
        ("a", "b"),
        [(2.0, 1.0, 30.0, 1e-14), (2.0, 1.0, 0.0, 1e-14), (1.5, 3.0, 2.0, 0.0)],
    ),
    "d_loop_body": (
        _d_loop,
        ("a", "b"),
        [(2.0, 1.0, 30.0, 1e-14), (2.0, 1.0, 0.0, 1e-14), (1.5, 3.0, 2.0, 0.0)],
    ),
    "d_picard": (_d_picard, ("a", "b"), [(0.6, 0.9, 7.0), (0.6, 0.9, 0.0), (1.2, -0.3, 1.0)]),
    "d_tail": (_d_tail, ("a", "b"), [(0.6, 0.9, 5.0), (0.6, 0.9, 0.0)]),
    "d_loop_switch": (
        _d_loop_switch,
        ("a", "b"),
        [(0.7, 0.8, 0.0, 4.0), (0.7, 0.8, 1.0, 4.0), (0.7, 0.8, 1.0, 0.0)],
    ),
    "d_switch": (
        _d_switch,
        ("a", "b"),
        [(0.8, 1.4, 0.0, 3.0), (0.8, 1.4, 1.0, 3.0), (0.8, 1.4, 2.0, 3.0), (0.8, 1.4, 2.0, 0.0)],
    ),
    "d_nested": (_d_nested, ("a", "b"), [(0.9, 0.5, 4.0, 3.0), (0.9, 0.5, 0.0, 3.0), (0.9, 0.5, 4.0, 0.0)]),
}


def _d_kernel(name):
    make = D_CASES[name][0]
    return make(name == "d_loop_evaluate") if make is _d_loop else make()


def dgen_kernels(looped_size: int = 1):
    """Every synthetic kernel and its Jacobian (one kernel, every direction in one pass) with the
    kernels the differentiation generates: (primal and callee kernels, the Differentiator). Loops
    of at least ``looped_size`` assignments get their tangent code once, run per direction."""
    from slipmaps.derive import tangent

    default, tangent.LOOPED_SIZE = tangent.LOOPED_SIZE, looped_size
    try:
        diff = tangent.Differentiator()
        primal = {}
        for name, (_, wrt, _) in D_CASES.items():
            kern = _d_kernel(name)
            primal[name] = kern
            diff.jacobian(kern, wrt, name=f"{name}_jacobian", summary=f"Jacobian of {name}.")
        diff.build()
    finally:
        tangent.LOOPED_SIZE = default
    return list(primal.values()) + [_d_inner(), _d_small()], diff


@pytest.fixture(scope="module", params=[1, 10**6], ids=["loops per direction", "loops unrolled"])
def dgen(request, tmp_path_factory):
    """The module of :func:`dgen_kernels` and its Differentiator: every loop's tangent code per
    direction, or every loop's unrolled."""
    kernels, diff = dgen_kernels(request.param)
    directory = tmp_path_factory.mktemp("ir_jacobians")
    return load_module(directory, "ir_jacobians", kernels + list(diff.kernels.values())), diff


def _central(fn, point, j, h):
    up, down = list(point), list(point)
    up[j] += h
    down[j] -= h
    a, b = fn(*up), fn(*down)
    assert a[-1] == OK and b[-1] == OK, (a, b)
    return (np.array(a[:-1]) - np.array(b[:-1])) / (2 * h)


@pytest.mark.parametrize("name", sorted(D_CASES))
def test_jacobian_in_one_pass_matches_central_differences(dgen, name):
    """The Jacobian kernel's values are the kernel's, its derivatives (outputs, then d output_i /
    d input_j row-major) the central differences' within their truncation and round-off (h = 1e-6:
    measured <= 1e-8 relative to the column's scale)."""
    mod, _ = dgen
    _, wrt, points = D_CASES[name]
    primal, jac = getattr(mod, name), getattr(mod, f"{name}_jacobian")
    n_out = len(_d_kernel(name).outputs.names())
    args = [a.name for a in _d_kernel(name).args]
    for point in points:
        res = jac(*point)
        ref = primal(*point)
        assert res[-1] == OK == ref[-1], (point, res, ref)
        np.testing.assert_allclose(res[:n_out], ref[:-1], rtol=1e-13, atol=1e-13)
        got = np.array(res[n_out:-1]).reshape(n_out, len(wrt))
        for j, w_ in enumerate(wrt):
            fd = _central(primal, point, args.index(w_), 1e-6)
            scale = max(1.0, float(np.abs(fd).max()))
            np.testing.assert_allclose(
                got[:, j], fd, rtol=0, atol=2e-8 * scale, err_msg=f"{name} d/d{w_} at {point}"
            )


def test_jacobian_kernels_share_callee_derivatives(dgen):
    """One derivative kernel per callee and set of active arguments: the calls differentiate
    d_inner along the caller's directions (a vector JVP: 4 active arguments, 2 directions) and
    d_small by its own Jacobian (2 active arguments), each generated once; no loop body is
    outlined, the switch branches that hold a loop are."""
    _, diff = dgen
    names = sorted(diff.kernels)
    assert sum(nm.startswith("d_inner_jvp2_") for nm in names) == 2  # d_calls' and d_switch's directions
    assert "d_small_jac_p_q" in names
    assert any(nm.startswith("d_switch_jacobian_") for nm in names)  # the branches (one holds a loop)
    assert not any(nm.startswith(("d_loop", "d_picard", "d_nested")) and nm[-1].isdigit() for nm in names)


def test_loop_tangents_are_computed_once_per_direction_in_a_loop():
    """A loop whose steps are stages, calls and switches of them computes its values once per pass
    and runs its tangent code, written once, per direction on the direction array (on the kernel's
    stack); a loop holding another loop carries a variable per tangent and direction."""
    _, diff = dgen_kernels(1)
    derived = diff.kernels
    src = render_module(list(derived.values()))
    picard = src.split("def d_picard_jacobian(", 1)[1].split("\ndef ", 1)[0]
    assert "for _j0 in range(2):" in picard and "_T = carray(stack(" in picard  # on the stack
    assert "d_u__j" in picard and "d_u__a" in picard  # per direction in the loop, loaded after it
    # a loop holding a switch: the tangent code per direction too, in the same branch as the values
    branching = src.split("def d_loop_switch_jacobian(", 1)[1].split("\ndef ", 1)[0]
    loop = branching.split("for _it0 in", 1)[1]
    per_direction = loop.split("for _j", 1)[1]
    assert "if k == 0.0:" in loop.split("for _j", 1)[0] and "if k == 0.0:" in per_direction
    nested = lower(derived["d_nested_jacobian"])
    assert any(n["kind"] == "loop" and n["packed"] for n in nested["body"])
    _, unrolled = dgen_kernels(10**6)
    assert "for _j" not in render_module(list(unrolled.kernels.values()))


def test_jacobian_of_zero_iterations_is_the_start_values(dgen):
    """max_iter = 0: no pass, the derivative is the start value's (d u / d b = 1/4 for u = 1 + b/4)."""
    mod, _ = dgen
    res = mod.d_loop_evaluate_jacobian(2.0, 1.0, 0.0, 1e-14)
    n_out = 3
    d = np.array(res[n_out:-1]).reshape(n_out, 2)
    assert res[0] == 1.25 and d[0].tolist() == [0.0, 0.25]
    assert res[2] == 0.0 and d[2].tolist() == [0.0, 0.0]  # passes: a count, no derivative


def test_jacobian_status_and_refused_derivatives(dgen):
    """A failing guard fails the Jacobian with the kernel's status and NaN outputs; an expression
    SymPy cannot differentiate in closed form is refused at generation."""
    from slipmaps.derive.tangent import Differentiator

    mod, _ = dgen
    res = mod.d_stages_jacobian(0.7, -1.0)
    assert res[-1] == FALL and all(math.isnan(val) for val in res[:-1])
    bad = _kernel("bad", _args(a_), (Stage(((u, sp.Function("g")(a_)),)),), _out("u"))
    diff = Differentiator()
    diff.jacobian(bad, ("a",), name="bad_jacobian", summary="refused")
    with pytest.raises(ValueError, match="not differentiable in closed form"):
        diff.build()


def test_choices_share_one_docstring(tmp_path):
    """A kernel whose docstring would repeat an earlier one's word for word (another choice of a
    specialized option) refers to it, its batch form to the earlier batch form; a kernel with other
    arguments keeps its own; the module still compiles and runs every one."""

    def choice(name, arg_y=y, scale=1):
        return Kernel(
            name=name,
            summary="test kernel of two choices",
            equations=("test",),
            args=(Arg(w, "w"), Arg(arg_y, "second argument")),
            steps=(Stage(((u, scale * w + arg_y),)),),
            outputs=_out("u"),
            layout=Layout(("w",), (arg_y.name,)),
        )

    kernels = [choice("choice_a"), choice("choice_b", scale=2), choice("other", arg_y=z)]
    text = render_module(kernels)
    docs = dict(re.findall(r'^def (\w+)\(.*?\n    """(.*?)"""', text, re.MULTILINE | re.DOTALL))
    assert "Arguments:" in docs["choice_a"] and "second argument" in docs["choice_a"]
    assert "Arguments:" not in docs["choice_b"] and ":func:`choice_a`" in docs["choice_b"]
    assert ":func:`choice_b`" in docs["choice_b_rows"]
    assert "Arguments:" in docs["other"] and "choice_a" not in docs["other"]
    mod = load_module(tmp_path, "choices", kernels)
    for name, expected in (("choice_a", 3.0), ("choice_b", 4.0)):
        assert kernels_.invoke(kernels[0], {"w": 1.0, "y": 2.0}, getattr(mod, name))[:1] == (expected,)
    assert kernels_.invoke(kernels[2], {"w": 1.0, "z": 2.0}, mod.other)[:1] == (3.0,)


def test_a_stage_at_zero_evaluates_its_values_at_zero_and_keeps_their_derivatives(tmp_path):
    """``Stage.zero``: the inputs named are 0 wherever the stage runs (a branch taken on that), so the
    generated values are the expressions at 0 (bit for bit, no term in them), while the derivative
    kernel differentiates first and evaluates at 0: d/dy of x + y x^2 is x^2 (derive/model/flight.py's
    leg held still)."""
    from slipmaps.derive.tangent import Differentiator

    at_zero = Stage(((u, w + y * w**2), (v, sp.cos(w) - y * sp.sin(w))), zero=(y,))
    kern = _kernel("at_zero", _args(w, y), (at_zero,), _out("u", "v"))
    diff = Differentiator()
    diff.jacobian(kern, ("w", "y"), name="at_zero_jacobian", summary="Jacobian of at_zero.")
    diff.build()
    text = render_module([kern, *diff.kernels.values()])
    body = text.split("def at_zero(", 1)[1].split("\ndef ", 1)[0]
    assert "    u = w\n    v = math.cos(w)\n" in body, body
    mod = load_module(tmp_path, "at_zero", [kern, *diff.kernels.values()])
    assert mod.at_zero(2.0, 0.0) == (2.0, math.cos(2.0), OK)
    res = mod.at_zero_jacobian(2.0, 0.0)
    assert res[-1] == OK and res[:2] == (2.0, math.cos(2.0))
    # d u/d w, d u/d y, d v/d w, d v/d y at y = 0
    assert np.allclose(res[2:6], (1.0, 4.0, -math.sin(2.0), -math.sin(2.0)), rtol=1e-15)


def test_a_copy_of_a_forwarded_value_is_read_where_it_is_used():
    """A forwarded value (a callee's out-array entry or a constant) renamed twice (a derivative taken
    from a callee's row as it is) is not named: the kernel's output reads the value itself."""
    a, b = sym("a"), sym("b")
    kernel = _kernel(
        "k_copies",
        _args(x),
        (Stage(((a, sp.Float(2.5)), (u, 2 * x))), Stage(((b, a),)), Stage(((w, b),))),
        _out("u", "w"),
    )
    low = lower(kernel)
    assigned = [n["name"] for n in low["body"] if n["kind"] == "assign"]
    assert not {"a", "b", "w"} & set(assigned), low["body"]
    assert [o["code"] for o in low["outputs"]] == ["u", "2.5"]
