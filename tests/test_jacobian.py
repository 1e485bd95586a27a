"""Jacobians of every map (slipmaps.stance_jacobian / apex_return_jacobian) against central differences.

Generated maps: forward-mode derivatives of the declaration (derive/tangent.py); "exact": the
variational equations of the compiled simulator composed with the flights' derivatives.

Agreement measure: per entry (|J - FD| - noise) / (|FD| + 1e-6 of the column's largest FD entry),
where noise = e max(|f|, 1) / h is the difference quotient's own error for a value f with relative
error e (100 eps for the generated maps, 1e-10 = ten times the integration tolerance for "exact"),
so that entries that are zero analytically (the liftoff leg length against anything) pass when the
quotient is noise.

Step h = 1e-6 of each input (1e-4 for "exact", whose values carry the integration's 1e-11 relative
error; the apex height and speed, the touchdown state: of max(1, |x|); the stiffness: of itself).
Measured on the human runner (k = 20 kN/m; k_c = 20, k_d = 24 kN/m where a map takes both),
2026-11-23: apex-return Jacobians of every generated map 0 (within the quotient's noise), "exact"
3.1e-8; stance Jacobians up to 4.4e-6 for the generated maps (gravity-type3's d liftoff_q_rd / d k,
an entry of -2e-7 (m/s) per N/m where the iterated map's round-off exceeds the 100 eps allowance;
the others <= 1.9e-6) and 1.3e-7 for "exact" (the quotient's O(h^2) error).
"""

from __future__ import annotations

import ast
import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
import slipmaps
import slipmaps.generated

P = slipmaps.HUMAN_RUNNER
VS = slipmaps.SlipParams(m=80.0, l0=1.0, k_c=20_000.0, k_d=24_000.0)
EPS = np.finfo(float).eps
REL_STEP = {"exact": 1e-4}  # else 1e-6: the exact values carry a 1e-11 relative integration error
#: Bounds from the measurement in the module docstring (about 4x the largest measured value).
BOUND = {"exact": 5e-7}
BOUND_GENERATED = 2e-5
#: Relative error of a value, as seen by a difference quotient: round-off, or for "exact" ten times
#: its integration tolerance (rtol 1e-11).
NOISE = {"exact": 1e-10}

NAMES = [m.name for m in slipmaps.maps()]
#: The maps whose c column at c = 0 is the derivative with the liftoff where the lossless leg lifts
#: off (the damped ``iterative``: its values there are the lossless map's, bit for bit; from above,
#: ``liftoff="force"`` moves the liftoff with c at first order when q_r_lo = l0, docs/damping.md):
#: its difference quotient from above is taken with ``liftoff="length"``, the same values at c = 0.
HELD_LIFTOFF_AT_C0 = {"iterative"}
#: A symmetric and a nonsymmetric touchdown (q_r, q_rd, q_th, q_thd) of the human runner.
TOUCHDOWNS = [(1.0, -1.55, 0.35, -4.6), (0.99, -1.2, 0.30, -5.2)]


def _held(name: str, inp: str, params: slipmaps.SlipParams) -> dict:
    """The options of the difference quotient of column ``inp`` (:data:`HELD_LIFTOFF_AT_C0`)."""
    return {"liftoff": "length"} if name in HELD_LIFTOFF_AT_C0 and inp == "c" and params.c == 0.0 else {}


def _stiffness_params(params: slipmaps.SlipParams, name: str, x: float) -> slipmaps.SlipParams:
    return params.with_(**{name: x})  # k sets both stiffnesses


def _params_for(name: str) -> slipmaps.SlipParams:
    info = next(m for m in slipmaps.maps() if m.name == name)
    return P if "constant_stiffness" in info.requires else VS


def _compare(name, jac, quotient, values, steps) -> float:
    """The largest disagreement (module docstring) of a Jacobian with difference quotients."""
    fd = np.array(quotient)
    # the difference quotient's own noise: round-off, or the integration's error for "exact"
    noise = NOISE.get(name, 100 * EPS) * np.maximum(np.abs(values), 1.0)[:, None] / np.asarray(steps)[None, :]
    scale = np.abs(fd) + 1e-6 * np.max(np.abs(fd), axis=0, keepdims=True)
    return float(np.max(np.maximum(np.abs(jac.matrix - fd) - noise, 0.0) / scale))


def _parameter_column(
    f, params: slipmaps.SlipParams, inp: str, step: float, outputs
) -> tuple[np.ndarray, float]:
    """(d outputs / d parameter ``inp``, the step) of ``f(x)``, the map with the parameter at x: a
    central difference at ``step`` times its value; the leg damping c at 0 (its domain's edge, the
    exact map's column a derivative from above) by a second-order one from above, at ``step`` times
    the critical damping 2 sqrt(k_c m)."""
    x0 = getattr(params, "k_c" if inp == "k" else inp)
    if inp == "c" and x0 == 0.0:
        h = step * 2.0 * math.sqrt(params.k_c * params.m)
        a, b, c = (f(i * h) for i in range(3))
        assert a.ok and b.ok and c.ok, (a.message, b.message, c.message)
        return np.array([(-c[o] + 4 * b[o] - 3 * a[o]) / (2 * h) for o in outputs]), h
    h = step * x0
    return _central(f, (x0,), 0, h, outputs), h


def _central(f, x0: tuple, j: int, h: float, outputs) -> np.ndarray:
    up, down = list(x0), list(x0)
    up[j] += h
    down[j] -= h
    a, b = f(*up), f(*down)
    assert a.ok and b.ok, (a.message, b.message)
    return np.array([(a[o] - b[o]) / (2 * h) for o in outputs])


#: Apex-return points (apex height, speed, touchdown angle, ground, retraction rate): running toward
#: +x onto a step up of 5 cm from a 1.1 m apex with the leg retracting at 0.5 rad/s, and toward -x
#: (the mirrored angle and rate) onto a step down of 3 cm; both fall 9-11 cm to touchdown, as the
#: flat-ground point (1.0, 5.0, 0.35) does 6 cm (a grazing touchdown's derivatives grow as
#: 1/sqrt(drop), beyond the difference quotients' reach); and the first with the leg held still (a
#: rate of 0: the touchdown time's closed form, whose rate column the differences at +-h check).
APEX_POINTS = [(1.1, 5.0, 0.35, 0.05, -0.5), (1.0, -5.0, -0.35, -0.03, 0.5), (1.1, 5.0, 0.35, 0.05, 0.0)]
APEX_NAMES = ("apex_height", "apex_speed", "touchdown_angle", "ground", "retraction_rate")


@pytest.mark.parametrize("point", APEX_POINTS, ids=["forward-step-up", "backward-step-down", "leg-held"])
@pytest.mark.parametrize("name", NAMES)
def test_apex_return_jacobian_matches_central_differences(name, point):
    """Every column, the ground's, the signed speed's and the retraction rate's included, against
    central differences."""
    params = _params_for(name)
    jac = slipmaps.apex_return_jacobian(name, params, *point[:3], ground=point[3], retraction_rate=point[4])
    assert jac.ok, jac.message
    assert jac.inputs[:5] == APEX_NAMES

    def apex_return(h, v, th, ground, rate, p=params, **held):
        return slipmaps.apex_return(name, p, h, v, th, ground=ground, retraction_rate=rate, **held)

    columns, steps = [], []
    for j, inp in enumerate(jac.inputs):
        if j < 5:
            h = REL_STEP.get(name, 1e-6) * max(1.0, abs(point[j]))
            columns.append(_central(apex_return, point, j, h, jac.outputs))
        else:

            def step(x, inp=inp):
                return apex_return(*point, p=_stiffness_params(params, inp, x), **_held(name, inp, params))

            column, h = _parameter_column(step, params, inp, REL_STEP.get(name, 1e-6), jac.outputs)
            columns.append(column)
        steps.append(h)
    values = np.array([jac.values[o] for o in jac.outputs])
    err = _compare(name, jac, np.array(columns).T, values, steps)
    assert err <= BOUND.get(name, BOUND_GENERATED), f"{name}: {err:.2e}"


def _stance_error(name: str, params, touchdown, options: dict) -> float:
    jac = slipmaps.stance_jacobian(name, params, touchdown, **options)
    assert jac.ok, jac.message
    assert jac.inputs[:4] == ("q_r_td", "q_rd_td", "q_th_td", "q_thd_td")

    def stance(p, td, **held):
        return slipmaps.stance(name, p, td, **{**options, **held})

    columns, steps, keep = [], [], []
    for j, inp in enumerate(jac.inputs):
        if np.isnan(jac.matrix[:, j]).all():
            # only the q_r_td column of a choice that assumes touchdown at the rest length
            assert inp == "q_r_td" and options, (name, options)
            continue
        keep.append(j)
        if j < 4:
            h = REL_STEP.get(name, 1e-6) * max(1.0, abs(touchdown[j]))
            if j == 0 and touchdown[0] + h > params.l0:
                # q_r_td = l0 cannot be moved up (q_r > l0 is invalid): the quotient from below
                a, b, c = (stance(params, (touchdown[0] - i * h, *touchdown[1:])) for i in range(3))
                columns.append(np.array([(3 * a[o] - 4 * b[o] + c[o]) / (2 * h) for o in jac.outputs]))
            else:
                columns.append(_central(lambda *x: stance(params, x), touchdown, j, h, jac.outputs))
        else:
            column, h = _parameter_column(
                lambda x, inp=inp: stance(
                    _stiffness_params(params, inp, x), touchdown, **_held(name, inp, params)
                ),
                params,
                inp,
                REL_STEP.get(name, 1e-6),
                jac.outputs,
            )
            columns.append(column)
        steps.append(h)
    assert keep, (name, options)
    values = np.array([jac.values[o] for o in jac.outputs])
    kept = dataclasses.replace(jac, matrix=jac.matrix[:, keep], inputs=tuple(jac.inputs[j] for j in keep))
    return _compare(name, kept, np.array(columns).T, values, steps)


@pytest.mark.parametrize("touchdown", TOUCHDOWNS)
@pytest.mark.parametrize("name", NAMES)
def test_stance_jacobian_matches_central_differences(name, touchdown):
    err = _stance_error(name, _params_for(name), touchdown, {})
    # the one-sided quotient at q_r_td = l0 has an O(h^2) error of its own (measured <= 3e-7)
    assert err <= BOUND.get(name, BOUND_GENERATED), f"{name}: {err:.2e}"


def _option_cases() -> list:
    """Every value of every choice option of every generated map, and a few passes for the iterated
    ones: the other branches and loops of the derivative kernels (no recompilation: options are
    run-time arguments)."""
    cases = []
    for info in slipmaps.maps():
        if info.ground_truth:
            continue  # "exact": its one choice, method="scipy", has no Jacobian (tested below)
        for o in info.options:
            if o.kind == "choice":
                cases += [(info.name, {o.name: c}) for c in o.choices if c != o.default]
            elif o.name == "iterations":  # three passes, whatever they converge to
                with_tol = any(t.name == "tol" for t in info.options)
                cases.append((info.name, {o.name: 3, **({"tol": 0} if with_tol else {})}))
    return cases


def test_option_cases_cover_every_generated_map_with_options():
    """The parametrization below is a filtered list: it must hold every generated map with options."""
    with_options = {m.name for m in slipmaps.maps() if not m.ground_truth and m.options}
    assert with_options and {name for name, _ in _option_cases()} == with_options


@pytest.mark.parametrize(("name", "options"), _option_cases(), ids=lambda x: str(x))
def test_stance_jacobian_at_every_option_choice(name, options):
    """Measured 2026-11-23: at most 6.4e-7 (iterative-report, iterations=3)."""
    err = _stance_error(name, _params_for(name), TOUCHDOWNS[0], options)
    assert err <= BOUND.get(name, BOUND_GENERATED), f"{name} {options}: {err:.2e}"


@pytest.mark.parametrize("name", ["geyer", "gravity-type4", "geyer-vs", "exact"])
def test_jacobian_values_are_the_maps_and_batches_equal_scalars(name):
    params = _params_for(name)
    speeds = np.array([4.0, 5.0, 6.0, np.nan])
    batch = slipmaps.apex_return_jacobian_batch(name, params, 1.0, speeds, 0.35)
    assert batch.matrix.shape == (4, len(batch.outputs), len(batch.inputs))
    assert list(batch.status[:3]) == [0, 0, 0]
    assert batch.status[3] == int(slipmaps.Status.INVALID_INPUT) and np.isnan(batch.matrix[3]).all()
    for i, v in enumerate(speeds[:3]):
        one = slipmaps.apex_return_jacobian(name, params, 1.0, v, 0.35)
        np.testing.assert_array_equal(batch.matrix[i], one.matrix)
        step = slipmaps.apex_return(name, params, 1.0, v, 0.35)
        for o in one.outputs:
            # the Jacobian kernel recomputes the values with its own operation order: round-off only
            assert one.values[o] == pytest.approx(step[o], rel=1e-12, abs=1e-12)
    td = np.array(TOUCHDOWNS)
    sb = slipmaps.stance_jacobian_batch(name, params, td)
    for i, row in enumerate(td):
        np.testing.assert_array_equal(sb.matrix[i], slipmaps.stance_jacobian(name, params, row).matrix)


def test_stiffness_columns_add_up_at_equal_stiffness():
    """At k_c = k_d, geyer-vs is Geyer et al.'s map: its d/dk_c + d/dk_d is Geyer's d/dk, and the
    exact map's sum is the derivative along k."""
    vs = slipmaps.apex_return_jacobian("geyer-vs", P, 1.0, 5.0, 0.35)
    geyer = slipmaps.apex_return_jacobian("geyer", P, 1.0, 5.0, 0.35)
    for o in geyer.outputs:
        assert vs[o, "k_c"] + vs[o, "k_d"] == pytest.approx(geyer[o, "k"], rel=1e-9, abs=1e-18)
        assert vs[o, "apex_height"] == pytest.approx(geyer[o, "apex_height"], rel=1e-9, abs=1e-15)


def test_jacobian_indexing_failures_and_scipy_refusal():
    jac = slipmaps.stance_jacobian("exact", P, TOUCHDOWNS[1])
    assert jac["liftoff", "touchdown"].shape == (4, 4)
    assert jac["t_stance", "k_d"] == jac.matrix[jac.outputs.index("t_stance"), jac.inputs.index("k_d")]
    with pytest.raises(KeyError, match="not among"):
        jac["apex_height", "k_d"]
    with pytest.raises(ValueError, match="method='scipy' has none"):
        slipmaps.stance_jacobian("exact", P, TOUCHDOWNS[1], method="scipy")
    bad = slipmaps.apex_return_jacobian("geyer", P, 0.5, 5.0, 0.35)  # apex below touchdown height
    assert bad.status == slipmaps.Status.APEX_TOO_LOW and np.isnan(bad.matrix).all()
    assert not bad.result.ok


def test_readme_derivatives_example_runs():
    """The Derivatives example (docs/getting_started.md, moved there from the README), run after the
    page's Python API example (whose names it uses)."""
    from documents import section_block

    page = "docs/getting_started.md"
    namespace: dict = {}
    exec(compile(section_block(page, "Python API"), page, "exec"), namespace)  # noqa: S102 - the project's docs
    exec(compile(section_block(page, "Derivatives"), page, "exec"), namespace)  # noqa: S102
    assert namespace["jac"].ok and namespace["jac"].inputs[-1] == "k"


def test_a_row_with_a_derivative_that_is_not_finite_is_numerical_range():
    """Every role kernel checks its whole row before it returns (generated/support.py's ``finite``,
    then ``fail``): a Jacobian whose values exist but a derivative does not (inf or NaN, at the first
    or the last derivative column) is NUMERICAL_RANGE with NaN everywhere, as the scalar API reports
    it; a finite row passes."""
    from numba import njit
    from slipmaps.generated import support
    from slipmaps.generated.status import STATUS_NUMERICAL_RANGE

    @njit
    def fail_range(row):  # fail is an intrinsic: callable from compiled code only
        return support.fail(row, STATUS_NUMERICAL_RANGE)

    n = 12
    good = np.arange(float(n))
    assert support.finite(good)
    for column in (4, n - 1):
        for bad in (np.inf, -np.inf, np.nan):
            row = good.copy()
            row[column] = bad
            assert not support.finite(row), (column, bad)
            code = fail_range(row)
            assert code == int(slipmaps.Status.NUMERICAL_RANGE) and np.isnan(row).all()
    # every role kernel ends in that check, or returns the result of a shared body that does
    # (derive/share.py); the batch form runs the same kernel per row
    roles = 0
    for path in Path(slipmaps.generated.__file__).resolve().parent.glob("*_jacobian.py"):
        source = path.read_text()
        funcs = {f.name: f for f in ast.parse(source).body if isinstance(f, ast.FunctionDef)}
        for name, f in funcs.items():
            if [a.arg for a in f.args.args] != ["x", "p", "out"]:
                continue
            roles += 1
            last = f.body[-1]
            if isinstance(last, ast.Return) and isinstance(last.value, ast.Call):
                callee = getattr(last.value.func, "id", "")
                if callee.endswith("_shared"):
                    f = funcs[callee]
            check = "not finite(out):\n        return fail(out, STATUS_NUMERICAL_RANGE)"
            assert check in ast.get_source_segment(source, f), (path.name, name)
    assert roles >= 2 * len(slipmaps.maps()), "role Jacobians check their rows"
