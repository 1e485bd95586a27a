"""Shared bodies (derive/share.py): kernels that differ only in the kernels they call are entry points
of one body that takes those callees as arguments, inlined into each entry point."""

from __future__ import annotations

import ast
import importlib.util
import json
import os
import subprocess
import sys
import textwrap
from dataclasses import replace
from pathlib import Path

import kernels
import slipmaps
import slipmaps.generated
from slipmaps.derive import generate
from slipmaps.derive.ir import Arg, Call, Field, Group, Kernel, Stage, sym
from slipmaps.derive.lower import lower
from slipmaps.derive.share import SUFFIX, share_bodies

GENERATED = Path(slipmaps.generated.__file__).parent
a, b, u, v = sym("a"), sym("b"), sym("u"), sym("v")


def _callee(name: str, scale: float) -> Kernel:
    """name(a) -> u = scale * a, a status."""
    return Kernel(
        name=name,
        summary=f"u = {scale} a",
        equations=(),
        args=(Arg(a, "a"),),
        steps=(Stage(((u, scale * a),)),),
        outputs=Group("", (Field("u", "u"),)),
        check_inputs=False,
    )


def _caller(name: str, callee: Kernel, offset: float = 1.0) -> Kernel:
    """name(a, b) -> v = callee(a) * b + offset."""
    return Kernel(
        name=name,
        summary="v = callee(a) b + offset",
        equations=(),
        args=(Arg(a, "a"), Arg(b, "b")),
        steps=(Call(callee, {"a": a}, {"u": "u"}), Stage(((v, u * b + offset),))),
        outputs=Group("", (Field("v", "v"),)),
    )


def _load(tmp_path: Path, lowered: list[dict]):
    text = generate.render_kernels(
        lowered,
        source="tests/test_share.py",
        module_doc="Kernels of tests/test_share.py.",
        depends=[],
        imports=[],
        status_module="slipmaps.generated.status",
        support_module="slipmaps.generated.support",
    )
    path = tmp_path / "share_kernels.py"
    path.write_text(text)
    spec = importlib.util.spec_from_file_location(f"_slipmaps_test_share_{abs(hash(str(tmp_path))):x}", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod, text


def test_kernels_differing_only_in_their_callee_share_one_body(tmp_path):
    c2, c3 = _callee("times_two", 2.0), _callee("times_three", 3.0)
    lowered = [lower(k) for k in (c2, c3, _caller("step_two", c2), _caller("step_three", c3))]
    out = share_bodies(lowered)
    # the callees, u = 2 a and u = 3 a, differ in a constant: they share a body too
    names = ["times" + SUFFIX, "times_two", "times_three", "step" + SUFFIX, "step_two", "step_three"]
    assert [k["name"] for k in out] == names
    body = out[3]
    assert body["shared_by"] == ["step_two", "step_three"] and body["shared_args"] == ["times"]
    assert body["params"] == "a, b, times" and body["inline"]
    assert [k["passes"] for k in out[4:]] == [["times_two"], ["times_three"]]
    assert [k["passes"] for k in out[1:3]] == [["2.0"], ["3.0"]]
    mod, text = _load(tmp_path, out)
    assert 'inline="always"' in text.split("def step_shared")[0].rsplit("@njit", 1)[1]
    # the entry points compute what the kernels they replace computed
    assert mod.step_two(1.5, 2.0) == (1.5 * 2.0 * 2.0 + 1.0, 0)
    assert mod.step_three(1.5, 2.0) == (1.5 * 3.0 * 2.0 + 1.0, 0)


def test_kernels_differing_in_a_constant_pass_it_to_the_shared_body(tmp_path):
    """The iterative maps' ``held`` zeroth iterate passes its flag as 1, the other choices as 0: a
    float constant in which kernels differ is an argument of their shared body."""
    c2, c3 = _callee("times_two", 2.0), _callee("times_three", 3.0)
    lowered = [lower(k) for k in (c2, c3, _caller("step_two", c2), _caller("step_three", c3, offset=2.5))]
    out = share_bodies(lowered)
    body = out[3]
    assert body["name"] == "step" + SUFFIX and body["params"] == "a, b, times, constant0"
    assert [k["passes"] for k in out[4:]] == [["times_two", "1.0"], ["times_three", "2.5"]]
    mod, text = _load(tmp_path, out)
    assert "each passing the kernel it calls as times and its constant as constant0" in " ".join(text.split())
    assert mod.step_two(1.5, 2.0) == (1.5 * 2.0 * 2.0 + 1.0, 0)
    assert mod.step_three(1.5, 2.0) == (1.5 * 3.0 * 2.0 + 2.5, 0)


def test_a_shared_bodys_comments_name_the_argument_not_the_first_members_callee(tmp_path):
    """A comment naming the member's callee (or the kernel whose Jacobian it calls: a word that
    starts the callee's name) names the shared body's argument; the words every member's comment
    has stay."""
    c2, c3 = _callee("times_two_jac", 2.0), _callee("times_three_jac", 3.0)

    def caller(name: str, callee: Kernel, comment: str) -> Kernel:
        k = _caller(name, callee)
        call = replace(k.steps[0], comment=comment)
        return replace(k, steps=(call, *k.steps[1:]))

    members = [
        caller("step_two", c2, "scaled by times_two, then by b"),
        caller("step_three", c3, "scaled by times_three, then by b"),
    ]
    out = share_bodies([lower(k) for k in (c2, c3, *members)])
    body = next(k for k in out if k["name"] == "step" + SUFFIX)
    assert body["shared_args"] == ["times_jac"]
    comments = [n["text"] for n in body["body"] if n["kind"] == "comment"]
    assert comments == ["scaled by times_jac, then by b"]
    _, text = _load(tmp_path, out)
    assert "# scaled by times_jac, then by b" in text and "times_two," not in text


def test_a_kernel_differing_in_more_than_callees_and_constants_keeps_its_body(monkeypatch):
    from slipmaps.derive import share

    c2, c3 = _callee("times_two", 2.0), _callee("times_three", 3.0)
    other = replace(
        _caller("step_three", c3), steps=(Call(c3, {"a": a}, {"u": "u"}), Stage(((v, u * b * b),)))
    )
    for pair in ((_caller("step_two", c2), other), (_caller("step_two", c2), _caller("step_three", c3, 2.5))):
        if pair[1] is not other:  # kernels differing in more constants than an argument list may take
            monkeypatch.setattr(share, "MAX_CONSTANTS", 0)
        lowered = [lower(k) for k in (c2, c3, *pair)]
        steps = [k for k in share_bodies(lowered) if k["name"].startswith("step")]
        assert [k["name"] for k in steps] == ["step_two", "step_three"]
        assert not any(k["shared_by"] or k["entry_of"] for k in steps)


def test_a_callee_numba_inlines_is_inlined_through_the_argument(tmp_path):
    """The zeroth iterates are ``inline="always"``: passed to the inlined shared body, numba inlines
    them into the entry point too (never compiled on their own)."""
    c2, c3 = _callee("times_two", 2.0), _callee("times_three", 3.0)
    c2, c3 = (replace(c, inline=True) for c in (c2, c3))
    out = share_bodies([lower(k) for k in (c2, c3, _caller("step_two", c2), _caller("step_three", c3))])
    assert out[2]["name"] == "step" + SUFFIX
    mod, _ = _load(tmp_path, out)
    assert mod.step_three(1.5, 2.0) == (1.5 * 3.0 * 2.0 + 1.0, 0)
    assert mod.times_three.signatures == [] and mod.step_shared.signatures == []


def test_sharing_is_deterministic():
    def build():
        c2, c3 = _callee("times_two", 2.0), _callee("times_three", 3.0)
        lowered = [lower(k) for k in (c2, c3, _caller("step_two", c2), _caller("step_three", c3))]
        return json.dumps(share_bodies(lowered), sort_keys=True, default=repr)

    assert build() == build()


def _shared_bodies() -> list[tuple[str, str, list[str]]]:
    """(module, shared body, its entry points) of every generated module."""
    out = []
    for path in sorted(GENERATED.glob("*.py")):
        tree = ast.parse(path.read_text())
        funcs = [n for n in tree.body if isinstance(n, ast.FunctionDef)]
        for f in funcs:
            if f.name.endswith(SUFFIX):
                entries = [
                    g.name
                    for g in funcs
                    if isinstance(g.body[-1], ast.Return)
                    and isinstance(g.body[-1].value, ast.Call)
                    and getattr(g.body[-1].value.func, "id", None) == f.name
                ]
                out.append((path.stem, f.name, entries))
    return out


def test_generated_shared_bodies_are_inlined_into_declared_entry_points():
    """Every shared body is inlined (a function argument of a compiled, not inlined, function is an
    address numba's cache refuses) and serves two or more declared kernels, each a docstring and one
    return statement. The iterative maps' kernels of every zeroth-iterate choice share
    their stance's and their apex return's bodies, and their Jacobians'."""
    bodies = _shared_bodies()
    assert bodies, "no shared body generated"
    for module, name, entries in bodies:
        text = (GENERATED / f"{module}.py").read_text()
        decorator = text.split(f"\ndef {name}(")[0].rsplit("\n@", 1)[1]
        assert 'inline="always"' in decorator, (module, name)
        assert len(entries) >= 2, (module, name)
        for entry in entries:
            declared = kernels.declaration(module, entry)
            assert declared.name == entry
            fn = next(n for n in ast.parse(text).body if isinstance(n, ast.FunctionDef) and n.name == entry)
            assert len(fn.body) == 2, entry  # the docstring and the return
    names = {(m, n) for m, n, _ in bodies}
    for map_ in ("iterative", "iterative_report"):
        for role in ("stance", "apex_return", "stance_jacobian", "apex_return_jacobian"):
            module = map_ + ("_jacobian" if role.endswith("jacobian") else "")
            assert (module, f"{map_}_{role}_zeroth{SUFFIX}") in names, (module, role)
    entries = {e for _, _, es in bodies for e in es}
    assert "iterative_stance_zeroth_gravity_type0" in entries
    assert "iterative_stance_zeroth_held" in entries  # its flag `held` passed as a constant


def test_entry_points_load_from_numbas_cache(tmp_path):
    """A fresh process compiles an entry point (numba's warnings as errors: no "cannot cache"), a
    second one loads it from numba's cache."""
    script = textwrap.dedent(
        """
        import warnings
        from numba.core.errors import NumbaWarning
        warnings.simplefilter("error", NumbaWarning)  # "cannot cache" among them
        import slipmaps
        from slipmaps.generated import iterative as g
        runner = slipmaps.HUMAN_RUNNER
        step = slipmaps.apex_return("iterative", runner, 1.0, 5.0, 0.35, zeroth="gravity-type1")
        assert step.status.name == "OK", step
        k = g.iterative_apex_return_zeroth_gravity_type1
        print(sum(k.stats.cache_hits.values()), sum(k.stats.cache_misses.values()))
        """
    )
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    runs = [
        subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, check=False)
        for _ in range(2)
    ]
    for run in runs:
        assert run.returncode == 0, run.stderr[-3000:]
    first, second = (tuple(map(int, run.stdout.split())) for run in runs)
    assert first == (0, 1) and second == (1, 0), (first, second)
