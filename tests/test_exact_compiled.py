"""The compiled exact simulator (generated/exact_stance.py, generated/dop853.py) against the solve_ivp
reference (runtime/exact/reference.py), and the ``"exact"`` map's ``method`` option.

Both integrate the polar stance equations (2)-(3) of the report with the same DOP853 algorithm,
tolerances, step cap, events and statuses, so they agree to round-off: each bound below is set
about 30x above the discrepancy measured over its cases (the comment gives the measurement).
"""

from __future__ import annotations

import inspect
import math

import numpy as np
import pytest
import slipmaps
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from slipmaps.generated import exact_stance as ec
from slipmaps.generated import exact_stance as ek
from slipmaps.generated import slip_model as gen
from slipmaps.generated.status import Status
from slipmaps.runtime.api import model, names
from slipmaps.runtime.api.params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from slipmaps.runtime.api.results import GROUPS
from slipmaps.runtime.exact import reference as sim

RTOL, ATOL = sim.DEFAULT_RTOL, sim.DEFAULT_ATOL

#: (params, apex height, apex speed, touchdown angle): symmetric (the human runner's fixed point at
#: 5 m/s, 0.41116 rad) and nonsymmetric steps, k_c == k_d and k_c != k_d, both parameter sets.
STEPS = [
    pytest.param(HUMAN_RUNNER, 1.0, 5.0, 0.41116492751713, id="human-symmetric"),
    pytest.param(HUMAN_RUNNER, 1.0, 5.0, 0.30, id="human-5mps-0.30"),
    pytest.param(HUMAN_RUNNER, 1.1, 3.0, 0.30, id="human-3mps-0.30"),
    pytest.param(ROBOT_HOPPER, 0.26, 1.5, 0.30, id="robot-1.5mps-0.30"),
    pytest.param(ROBOT_HOPPER, 0.26, 1.2, 0.30, id="robot-1.2mps-0.30"),
    pytest.param(HUMAN_RUNNER.with_(k_d=25_000.0), 1.0, 5.0, 0.30, id="human-kd25k"),
    pytest.param(HUMAN_RUNNER.with_(k_d=17_000.0), 1.0, 5.0, 0.35, id="human-kd17k"),
    pytest.param(ROBOT_HOPPER.with_(k_d=1_800.0, g_s=9.0), 0.26, 1.5, 0.30, id="robot-kd1.8k-gs9"),
    pytest.param(
        ROBOT_HOPPER.with_(k_c=1_200.0, q_r_td=0.24, q_r_lo=0.23), 0.26, 1.2, 0.35, id="robot-kc1.2k-short"
    ),
]


def _stance_row(r: sim.StanceResult | sim.StepResult) -> dict[str, float]:
    ref = {"t_bottom": r.t_bottom, "t_stance": r.t_stance}
    for group, state in (("bottom", r.bottom), ("liftoff", r.liftoff)):
        ref.update(zip(GROUPS[group], state, strict=True))
    return ref


def _rel(a: float, b: float) -> float:
    return abs(a - b) / max(1.0, abs(b))


def _energy(p: SlipParams, state, k: float) -> float:
    return float(gen.stance_energy(*state, p.m, p.l0, k, p.g_s))


def _compiled_step(params: SlipParams, height, speed, angle) -> tuple[Status, dict[str, float]]:
    """The exact map's step (the generated composition around the compiled stance): its apex-return
    outputs, and its stance's (the bottom) from the same touchdown."""
    ap = slipmaps.apex_return("exact", params, height, speed, angle)
    ref = sim.simulate_step(params, height, speed, angle)
    st = slipmaps.stance("exact", params, ref.touchdown) if ref.touchdown is not None else None
    values = {**(st.values if st is not None else {}), **ap.values}
    return ap.status, values if ap.ok else dict.fromkeys(values, math.nan)


def _compiled_stance(p: SlipParams, td, t_max: float | None = None) -> tuple[Status, np.ndarray]:
    out = np.empty(ec.N_STANCE)
    t_end = sim.default_t_max(p) if t_max is None else t_max
    code = ec.stance_into(*td, ec.Stance(p.m, p.l0, p.k_c, p.k_d, p.g_s, p.q_r_lo, RTOL, ATOL, t_end), out)
    return Status(int(code)), out


# ----------------------------------------------------------------------------------------------
# 1. Agreement with solve_ivp on complete steps, and energy conservation per subphase
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(("params", "height", "speed", "angle"), STEPS)
def test_compiled_step_matches_solve_ivp(params, height, speed, angle):
    ref = sim.simulate_step(params, height, speed, angle)
    status, got = _compiled_step(params, height, speed, angle)
    assert ref.status == status == Status.OK, ref.message
    expected = {names.public(k): v for k, v in sim.step_values(ref).items()}  # the results' names
    assert set(expected) == set(got)
    # Measured over STEPS: bottom states 1.6e-15, liftoff states 3.8e-15 (relative to max(1, |x|)),
    # t_bottom and t_stance 4.4e-16 s, next apex 3.6e-15.
    for name, value in expected.items():
        assert _rel(got[name], value) < 1e-13, (name, got[name], value)
    for name in ("t_bottom", "t_stance"):
        assert abs(got[name] - expected[name]) < 1e-14, name


@pytest.mark.parametrize(("params", "height", "speed", "angle"), STEPS)
def test_energy_is_conserved_within_each_subphase(params, height, speed, angle):
    """Eq (27) with k_c from touchdown to the bottom and with k_d from the bottom to liftoff."""
    status, got = _compiled_step(params, height, speed, angle)
    assert status == Status.OK
    td = sim.simulate_step(params, height, speed, angle).touchdown  # closed-form flight, no stance
    bottom = [got[n] for n in GROUPS["bottom"]]
    liftoff = [got[n] for n in GROUPS["liftoff"]]
    e_td = _energy(params, td, params.k_c)
    drift_c = abs(_energy(params, bottom, params.k_c) - e_td) / abs(e_td)
    e_b = _energy(params, bottom, params.k_d)
    drift_d = abs(_energy(params, liftoff, params.k_d) - e_b) / abs(e_b)
    # Measured over STEPS: 3.5e-12 (compression), 7.7e-12 (decompression), as solve_ivp's.
    assert drift_c < 2e-10, drift_c
    assert drift_d < 2e-10, drift_d


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    robot=st.booleans(),
    kd_ratio=st.one_of(st.just(1.0), st.floats(0.5, 1.5)),
    q_r=st.floats(0.8, 1.0),
    q_rd=st.floats(0.05, 1.0),
    q_th=st.floats(-0.6, 0.6),
    q_thd=st.floats(-2.0, 0.5),
)
def test_random_touchdowns_match_solve_ivp(robot, kd_ratio, q_r, q_rd, q_th, q_thd):
    """Touchdowns in units of l0 and sqrt(g l0): q_r l0, -q_rd sqrt(g l0), q_th, q_thd sqrt(g/l0)."""
    base = ROBOT_HOPPER if robot else HUMAN_RUNNER
    p = base.with_(k_d=base.k_c * kd_ratio)
    s = math.sqrt(p.g_s * p.l0)
    td = (q_r * p.l0, -q_rd * s, q_th, q_thd * s / p.l0)
    ref = sim.simulate_stance(p, td)
    res = slipmaps.stance("exact", p, td)
    status, got = res.status, res.values
    assert status == ref.status, ref.message
    if status == Status.OK:
        # Measured over 1463 such stances (1500 drawn): 6.9e-14 relative, times 3.2e-15 s.
        for name, value in _stance_row(ref).items():
            assert _rel(got[name], value) < 2e-12, (name, got[name], value)
    else:
        assert all(math.isnan(v) for v in got.values())


_SOLVE = {}


def _compressions(field, tds, p: SlipParams):
    """dop853.solve's compression phase from each touchdown with ``field``: (code, t_end, event,
    steps, evaluations) and the end state, per row."""
    if not _SOLVE:
        from numba import njit
        from slipmaps.generated import dop853

        @njit
        def run(field, tds, p5, pe, direction, cap, out):
            for i in range(tds.shape[0]):
                y_end = np.empty(4)
                code, t_end, event, steps, evaluations = dop853.solve(
                    field, p5, ec.stance_events, pe, direction, 0.0, tds[i], 10.0, 1e-11, 1e-12, cap,
                    4, y_end, math.inf, y_end, dop853.GOES_ON,
                )  # fmt: skip
                out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4] = code, t_end, event, steps, evaluations
                out[i, 5:] = y_end

        _SOLVE["run"] = run
        _SOLVE["loops"] = njit(ec.polar_field.py_func)  # a second dispatcher: not registered
    out = np.empty((len(tds), 9))
    pe = ec.event_record(ec.Stance(p.m, p.l0, p.k_c, p.k_d, p.g_s, p.q_r_lo, 1e-11, 1e-12, 10.0, p.c))
    cap = ec.step_cap(p.m, p.l0, p.k_c, p.g_s, 1e-11)
    field = _SOLVE["loops"] if field is None else field
    p5 = (p.m, p.l0, p.k_c, p.g_s, p.c)
    _SOLVE["run"](field, tds, p5, pe, np.array(ec.COMPRESSION_DIRECTIONS), cap, out)
    return out


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    q_rd=st.lists(st.floats(0.05, 1.0), min_size=1, max_size=8),
    q_th=st.floats(-0.6, 0.6),
    q_thd=st.floats(-2.0, 0.5),
)
def test_written_out_step_equals_the_loops_bitwise(q_rd, q_th, q_thd):
    """dop853.static's state_length: the polar field's step with its 4 components written out (the
    registered field) and the step's loops (the same function, not registered) take the same steps
    and evaluations to the same states, bitwise."""
    p = HUMAN_RUNNER
    s = math.sqrt(p.g_s * p.l0)
    tds = np.array([(p.l0, -v * s, q_th, q_thd * s / p.l0) for v in q_rd])
    written, loops = _compressions(ec.polar_field, tds, p), _compressions(None, tds, p)
    assert np.all(written[:, 0] == 1), written[:, 0]  # every compression ends at its bottom event
    np.testing.assert_array_equal(written, loops)


def test_static_refuses_a_length_it_does_not_write_out():
    from slipmaps.generated import dop853

    with pytest.raises(ValueError, match="state_length"):
        dop853.static(ec.stance_events, 28)
    with pytest.raises(ValueError, match="state_length"):
        dop853.static(ec.polar_field)  # registered with 4: per function


# ----------------------------------------------------------------------------------------------
# 2. Every failure status of the reference, on the same inputs
# ----------------------------------------------------------------------------------------------
FAILING_STEPS = [
    pytest.param(HUMAN_RUNNER, 0.9, 5.0, 0.4, Status.APEX_TOO_LOW, id="apex-too-low"),
    pytest.param(HUMAN_RUNNER, 0.9, 5.0, -0.5, Status.TOUCHDOWN_NOT_COMPRESSING, id="extending-leg"),
    pytest.param(HUMAN_RUNNER, 0.2, 0.3, 1.4, Status.FALL, id="fall-decompression"),
    pytest.param(HUMAN_RUNNER.with_(k=2_000.0), 0.2, 1.0, 1.4, Status.FALL, id="fall-compression"),
    pytest.param(HUMAN_RUNNER, 1.0, 0.2, 0.3, Status.LIFTOFF_BACKWARD, id="liftoff-backward"),
    pytest.param(HUMAN_RUNNER, 1.0, 5.0, 0.2, Status.LIFTOFF_DOWNWARD, id="liftoff-downward"),
    pytest.param(HUMAN_RUNNER.with_(k_d=1_000.0), 1.1, 0.0, 0.0, Status.RECOMPRESSION, id="kd-cannot-extend"),
    pytest.param(HUMAN_RUNNER.with_(k_d=9_000.0), 1.1, 0.0, 0.0, Status.RECOMPRESSION, id="recompression"),
    pytest.param(HUMAN_RUNNER.with_(q_r_lo=0.5), 1.0, 5.0, 0.4, Status.NO_LIFTOFF, id="bottom-above-q_r_lo"),
]


@pytest.mark.parametrize(("params", "height", "speed", "angle", "status"), FAILING_STEPS)
def test_failures_match_solve_ivp(params, height, speed, angle, status):
    ref = sim.simulate_step(params, height, speed, angle)
    got_status, got = _compiled_step(params, height, speed, angle)
    assert ref.status == got_status == status, ref.message
    assert all(math.isnan(v) for v in got.values())
    api = slipmaps.apex_return("exact", params, height, speed, angle)
    assert api.status == status and math.isnan(api.next_apex_height)


def test_stance_failures_match_solve_ivp():
    td = (1.0, -1.0, 0.3, -4.0)
    for t_max in (0.01, 0.1):  # t_max before the bottom, and between the bottom and liftoff
        ref = sim.simulate_stance(HUMAN_RUNNER, td, t_max=t_max)
        assert ref.status == _compiled_stance(HUMAN_RUNNER, td, t_max)[0] == Status.NO_LIFTOFF
    for q_rd in (0.0, 0.1):
        td = (1.0, q_rd, 0.3, -4.0)
        assert sim.simulate_stance(HUMAN_RUNNER, td).status == Status.TOUCHDOWN_NOT_COMPRESSING
        assert _compiled_stance(HUMAN_RUNNER, td)[0] == Status.TOUCHDOWN_NOT_COMPRESSING
    collapsed = (0.5 * sim.COLLAPSE_FRACTION * HUMAN_RUNNER.l0, -1.0, 0.3, -4.0)
    assert sim.simulate_stance(HUMAN_RUNNER, collapsed).status == Status.FALL
    assert _compiled_stance(HUMAN_RUNNER, collapsed)[0] == Status.FALL


# ----------------------------------------------------------------------------------------------
# 3. Batches: rows equal scalar calls exactly, invalid rows are INVALID_INPUT
# ----------------------------------------------------------------------------------------------
def test_stance_batch_rows_equal_scalar_calls_and_invalid_rows_get_invalid_input():
    p = HUMAN_RUNNER.with_(k_d=22_000.0)
    rows = np.array(
        [
            (1.0, -1.5, 0.35, -4.5),
            (0.98, -1.0, -0.1, -3.0),
            (1.0, 0.5, 0.3, -4.0),  # TOUCHDOWN_NOT_COMPRESSING
            (math.nan, -1.0, 0.3, -4.0),
            (1.2, -1.0, 0.3, -4.0),  # q_r > l0
            (0.0, -1.0, 0.3, -4.0),  # q_r = 0
            (1.0, -1.0, math.pi / 2, -4.0),
            (1.0, -1.0, 0.3, math.inf),
        ]
    )
    res = slipmaps.stance_batch("exact", p, rows)
    assert list(res["status"][2:]) == [Status.TOUCHDOWN_NOT_COMPRESSING] + [Status.INVALID_INPUT] * 5
    for i in range(3):
        one = slipmaps.stance("exact", p, rows[i])
        assert res["status"][i] == one.status
        for name, value in one.values.items():
            assert res[name][i] == value or (math.isnan(value) and math.isnan(res[name][i])), name
    assert np.isnan(res["liftoff"][2:]).all()


def test_apex_batch_rows_equal_scalar_calls_and_invalid_rows_get_invalid_input():
    p = ROBOT_HOPPER
    heights = np.array([0.26, 0.26, 0.20, -0.1, math.nan, 0.26, 0.26])
    speeds = np.array([1.5, 1.2, 1.5, 1.5, 1.5, math.inf, 1.5])  # (a negative speed runs toward -x)
    angles = np.array([0.30, 0.35, 0.30, 0.30, 0.30, 0.30, 1.6])
    res = slipmaps.apex_return_batch("exact", p, heights, speeds, angles)
    assert list(res["status"][2:]) == [Status.APEX_TOO_LOW] + [Status.INVALID_INPUT] * 4
    for i in range(3):
        one = slipmaps.apex_return("exact", p, heights[i], speeds[i], angles[i])
        assert res["status"][i] == one.status
        for name, value in one.values.items():
            assert res[name][i] == value or (math.isnan(value) and math.isnan(res[name][i])), name
    # Broadcasting keeps the shape, as for the generated maps.
    grid = slipmaps.apex_return_batch("exact", p, 0.26, np.array([1.2, 1.5]), np.array([[0.28], [0.32]]))
    assert grid.shape == (2, 2) and grid["liftoff"].shape == (2, 2, 4) and grid.ok.all()
    assert (
        grid["next_apex_height"][1, 0] == slipmaps.apex_return("exact", p, 0.26, 1.2, 0.32).next_apex_height
    )


# ----------------------------------------------------------------------------------------------
# 4. The map's method option
# ----------------------------------------------------------------------------------------------
def test_method_option_defaults_to_compiled_and_scipy_is_the_reference():
    exact = slipmaps.runtime.api.index.get("exact")
    assert exact.option("method").default == "compiled"
    assert exact.option("method").choices == ("compiled", "scipy")
    p, td = HUMAN_RUNNER.with_(k_d=25_000.0), (1.0, -1.5, 0.35, -4.5)
    compiled = slipmaps.stance("exact", p, td)
    scipy = slipmaps.stance("exact", p, td, method="scipy")
    assert compiled.ok and scipy.ok and compiled.inputs["options"]["method"] == "compiled"
    # Measured: 4.7e-15 relative.
    for name, value in scipy.values.items():
        assert _rel(compiled[name], value) < 1e-13, name
    batch = slipmaps.stance_batch("exact", p, [td, (1.0, 0.5, 0.3, -4.0)], method="scipy")
    assert list(batch["status"]) == [Status.OK, Status.TOUCHDOWN_NOT_COMPRESSING]
    assert batch["t_stance"][0] == scipy.t_stance
    with pytest.raises(ValueError, match="'compiled', 'scipy'"):
        slipmaps.stance("exact", p, td, method="numba")


# ----------------------------------------------------------------------------------------------
# 5. The external kernels (generated/exact_stance.py): the halves and the state at a time
# ----------------------------------------------------------------------------------------------
#: The code of the default liftoff option (the leg force's zero; at c = 0 the same stance as q_r_lo).
FORCE = float(ek.LIFTOFF_FORCE)


def _args(p: SlipParams) -> tuple[float, ...]:
    """kernels.stance / state_at's parameters after the touchdown state."""
    return (p.m, p.l0, p.k_c, p.k_d, p.g_s, p.c, p.q_r_lo, RTOL, ATOL, FORCE)


def _compression_args(p: SlipParams) -> tuple[float, ...]:
    """kernels.compression's parameters after the touchdown state."""
    return (p.m, p.l0, p.k_c, p.g_s, p.q_r_lo, p.c, RTOL, ATOL)


def _decompression_args(p: SlipParams) -> tuple[float, ...]:
    """kernels.decompression's parameters after the bottom state."""
    return (p.m, p.l0, p.k_d, p.g_s, p.q_r_lo, p.c, RTOL, ATOL, FORCE)


def _halves(p: SlipParams, td) -> tuple[tuple, tuple | None]:
    down = ek.compression(*td, *_compression_args(p))
    if down[-1] != Status.OK:
        return down, None
    return down, ek.decompression(*down[1:5], *_decompression_args(p))


def _step_touchdown(p: SlipParams, height: float, speed: float, angle: float) -> tuple[float, ...]:
    _, td = model.call(
        "apex_to_touchdown", b_y_apex=height, b_xd_apex=speed, q_th_td=angle, q_r_td=p.q_r_td, g_f=p.g_f
    )
    return tuple(td[f"touchdown_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd"))


def _max_rel(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.max(np.abs(a - b) / np.maximum(1.0, np.abs(b))))


@pytest.mark.parametrize(("params", "height", "speed", "angle"), STEPS)
def test_compression_then_decompression_is_the_stance(params, height, speed, angle):
    td = _step_touchdown(params, height, speed, angle)
    stance = ek.stance(*td, *_args(params))
    down, up = _halves(params, td)
    assert stance[-1] == down[-1] == up[-1] == Status.OK
    t_bottom, t_stance, bottom, liftoff = stance[0], stance[1], stance[2:6], stance[6:10]
    # The compression is the stance's own integration: bitwise equal (measured 0 over STEPS and
    # 2910 random stances). The decompression restarts the clock at the bottom (t_half from 0):
    # measured over STEPS liftoff 3.5e-15 (relative to max(1, |x|)), t_stance 2.5e-16 s.
    assert down[0] == t_bottom and down[1:5] == bottom and down[2] == 0.0
    assert _max_rel(up[1:5], liftoff) < 1e-13, (up[1:5], liftoff)
    assert abs(down[0] + up[0] - t_stance) < 1e-14


def test_halves_compose_to_the_stance_on_random_touchdowns():
    """Touchdowns as test_random_touchdowns_match_solve_ivp's, half of them with k_c != k_d."""
    rng = np.random.default_rng(3)
    worst_liftoff = worst_time = 0.0
    seen = set()
    for _ in range(400):
        base = ROBOT_HOPPER if rng.random() < 0.5 else HUMAN_RUNNER
        p = base.with_(k_d=base.k_c * (1.0 if rng.random() < 0.5 else rng.uniform(0.5, 1.5)))
        s = math.sqrt(p.g_s * p.l0)
        td = (
            rng.uniform(0.8, 1.0) * p.l0,
            -rng.uniform(0.05, 1.0) * s,
            rng.uniform(-0.6, 0.6),
            rng.uniform(-2.0, 0.5) * s / p.l0,
        )
        stance = ek.stance(*td, *_args(p))
        down, up = _halves(p, td)
        status = down[-1] if up is None else up[-1]
        assert status == stance[-1], (td, p)
        seen.add(Status(int(status)))
        if status == Status.OK:
            assert down[:5] == (stance[0], *stance[2:6])
            worst_liftoff = max(worst_liftoff, _max_rel(up[1:5], stance[6:10]))
            worst_time = max(worst_time, abs(down[0] + up[0] - stance[1]))
        else:
            assert all(math.isnan(x) for x in stance[:-1])
    assert seen == {Status.OK, Status.RECOMPRESSION}
    # Measured over 2910 such stances: liftoff 2.5e-14, t_stance 2.2e-15 s.
    assert worst_liftoff < 5e-13, worst_liftoff
    assert worst_time < 5e-14, worst_time


def test_halves_split_the_stance_checks_at_the_bottom():
    # A bottom above q_r_lo is the decompression's NO_LIFTOFF, not the compression's failure.
    p = HUMAN_RUNNER.with_(q_r_lo=0.5)
    td = _step_touchdown(p, 1.0, 5.0, 0.4)
    assert ek.stance(*td, *_args(p))[-1] == Status.NO_LIFTOFF
    down, up = _halves(p, td)
    assert down[-1] == Status.OK and down[1] >= p.q_r_lo and down[2] == 0.0
    assert up[-1] == Status.NO_LIFTOFF and all(math.isnan(x) for x in up[:-1])
    # A k_d spring that cannot extend the leg at the bottom (test_failures_match_solve_ivp's).
    for k_d in (1_000.0, 9_000.0):
        p = HUMAN_RUNNER.with_(k_d=k_d)
        td = _step_touchdown(p, 1.1, 0.0, 0.0)
        down, up = _halves(p, td)
        assert ek.stance(*td, *_args(p))[-1] == up[-1] == Status.RECOMPRESSION and down[-1] == Status.OK
    # The touchdown checks are the compression's.
    p = HUMAN_RUNNER
    for td, status in (
        ((1.0, 0.0, 0.3, -4.0), Status.TOUCHDOWN_NOT_COMPRESSING),
        ((0.5 * sim.COLLAPSE_FRACTION, -1.0, 0.3, -4.0), Status.FALL),
    ):
        assert ek.compression(*td, *_compression_args(p))[-1] == status
        assert ek.stance(*td, *_args(p))[-1] == status
    # q_rd_b is not read by the decompression (0 at the bottom).
    down, _ = _halves(p, _step_touchdown(p, 1.0, 5.0, 0.35))
    q_r, _, q_th, q_thd = down[1:5]
    ups = {ek.decompression(q_r, q_rd, q_th, q_thd, *_decompression_args(p)) for q_rd in (0.0, -3.0, 5.0)}
    assert len(ups) == 1 and next(iter(ups))[-1] == Status.OK


@pytest.mark.parametrize(("params", "height", "speed", "angle"), STEPS)
def test_state_at_matches_solve_ivp_dense_output(params, height, speed, angle):
    td = _step_touchdown(params, height, speed, angle)
    ref = sim.simulate_stance(params, td, dense=True)
    assert ref.ok
    worst = 0.0
    for t, state in zip(ref.t, ref.states.T, strict=True):  # 8 samples per step, bottom and liftoff
        got = ek.state_at(t, *td, *_args(params))
        assert got[-1] == Status.OK
        worst = max(worst, _max_rel(got[:4], state))
    # Measured over STEPS (1081 samples): 4.6e-14, in q_rd after the bottom: the two simulators'
    # bottom times differ by ~4e-16 s, times the radial acceleration there (~100 m/s^2).
    assert worst < 1e-12, worst
    # The ends are the stance's own states, exactly: touchdown, bottom (q_rd = 0), liftoff.
    stance = ek.stance(*td, *_args(params))
    assert ek.state_at(0.0, *td, *_args(params))[:4] == td
    assert ek.state_at(stance[0], *td, *_args(params))[:4] == stance[2:6]
    assert ek.state_at(stance[1], *td, *_args(params))[:4] == stance[6:10]


@pytest.mark.parametrize(("params", "height", "speed", "angle"), STEPS[::2])
def test_state_at_continues_the_stance_equations_beyond_liftoff(params, height, speed, angle):
    """Beyond liftoff: the stance equations with k_d from the liftoff state, no event (as the
    approximate maps' closed forms), against solve_ivp's dense output from the same state."""
    td = _step_touchdown(params, height, speed, angle)
    ref = sim.simulate_stance(params, td)
    t_max = sim.default_t_max(params)
    p = params
    sol = solve_ivp(
        lambda _t, y: gen.stance_polar_rhs(*y, p.m, p.l0, p.k_d, p.g_s),
        (ref.t_stance, t_max),
        np.array(ref.liftoff),
        method="DOP853",
        rtol=RTOL,
        atol=ATOL,
        max_step=sim.max_step(p.m, p.l0, p.k_d, p.g_s),
        dense_output=True,
    )
    worst = 0.0
    for t in ref.t_stance * (1.0 + np.linspace(0.0, 1.0, 41)):
        got = ek.state_at(t, *td, *_args(p))
        assert got[-1] == Status.OK
        worst = max(worst, _max_rel(got[:4], sol.sol(t)))
    # Measured over STEPS (41 times each up to twice the stance time): 3.9e-14.
    assert worst < 1e-12, worst
    assert ek.state_at(t_max, *td, *_args(p))[-1] == Status.OK


def test_state_at_has_the_stance_status():
    p = HUMAN_RUNNER.with_(q_r_lo=0.5)  # NO_LIFTOFF: no state, even before the bottom
    td = _step_touchdown(p, 1.0, 5.0, 0.4)
    for t in (0.0, 0.01, 0.2):
        got = ek.state_at(t, *td, *_args(p))
        assert got[-1] == Status.NO_LIFTOFF and all(math.isnan(x) for x in got[:4])


def _jacobian_tuple(*args):
    """The external stance Jacobian (it writes its values and the Jacobian into an array, derive/lower.py's
    abi) as a tuple of its values and the status, like the other external kernels."""
    out = np.empty(ek.N_STANCE * (1 + ek.N_IN))
    code = ek.stance_jacobian(*args, out)
    return (*out, code)


def test_external_kernels_refuse_invalid_inputs():
    p = HUMAN_RUNNER
    td = (0.99, -1.5, 0.35, -4.5)
    bottom = ek.compression(*td, *_compression_args(p))[1:5]
    calls = {
        "stance": (ek.stance, (*td, *_args(p))),
        "stance_jacobian": (_jacobian_tuple, (*td, *_args(p))),
        "compression": (ek.compression, (*td, *_compression_args(p))),
        "decompression": (ek.decompression, (*bottom, *_decompression_args(p))),
        "state_at": (ek.state_at, (0.05, *td, *_args(p))),
    }
    for name, (kernel, args) in calls.items():
        names = list(inspect.signature(getattr(ek, name).py_func).parameters)
        at = {a: names.index(a) for a in ("m", "q_r_lo", "c", "rtol", "atol")}
        assert kernel(*args)[-1] == Status.OK, name
        state = 1 if name == "state_at" else 0  # the first argument of the state
        bad = [(i, x) for i in range(len(args)) for x in (math.nan, math.inf, -math.inf)]
        bad += [(state, 0.0), (state, 1.2 * p.l0), (state, -0.5)]  # q_r outside (0, l0]
        bad += [(state + 2, math.pi / 2), (state + 2, -2.0)]  # |q_th| >= pi/2
        bad += [(at["m"], 0.0), (at["rtol"], 0.0), (at["atol"], -1e-12), (at["q_r_lo"], 1.1 * p.l0)]
        bad += [(at["c"], -1e-9)]  # a negative damping
        if "liftoff" in names:
            bad += [(names.index("liftoff"), 2.0), (names.index("liftoff"), 0.5)]  # not a choice's code
        if name == "state_at":
            bad += [(0, -1e-9), (0, 2.0 * sim.default_t_max(p))]  # t outside [0, t_max]
        for i, x in bad:
            got = kernel(*args[:i], x, *args[i + 1 :])
            assert got[-1] == Status.INVALID_INPUT, (name, i, x)
            assert all(math.isnan(v) for v in got[:-1]), (name, i, x)


# ----------------------------------------------------------------------------------------------
# 6. Mirror symmetry x -> -x: the stance equations are even in (q_r, q_rd) and odd in (q_th, q_thd)
# ----------------------------------------------------------------------------------------------
#: The sign of each polar component under the mirror (q_r, q_rd, q_th, q_thd).
MIRROR = np.array([1.0, 1.0, -1.0, -1.0])
#: ... of each output of kernels.stance (t_bottom, t_stance, bottom, liftoff).
MIRROR_STANCE = np.array([1.0, 1.0, *MIRROR, *MIRROR])
#: ... of each output of the halves (t_half, end state).
MIRROR_HALF = np.array([1.0, *MIRROR])


def _mirror_cases(n: int, seed: int):
    """Random touchdowns running either way (q_th of both signs), k_c != k_d, both parameter sets."""
    rng = np.random.default_rng(seed)
    for _ in range(n):
        base = ROBOT_HOPPER if rng.random() < 0.5 else HUMAN_RUNNER
        p = base.with_(k_d=base.k_c * rng.uniform(0.7, 1.3))
        s = math.sqrt(p.g_s * p.l0)
        td = np.array(
            (
                rng.uniform(0.8, 1.0) * p.l0,
                -rng.uniform(0.05, 1.0) * s,
                rng.uniform(-0.6, 0.6),
                rng.uniform(-2.0, 0.5) * s / p.l0,
            )
        )
        yield p, td


def _mirrored(got, want, signs) -> float:
    """max |got - signs * want| relative to max(1, |want|); statuses equal, NaN where NaN."""
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    assert got[-1] == want[-1]
    assert np.array_equal(np.isnan(got), np.isnan(want))
    if want[-1] != Status.OK:
        return 0.0
    return _max_rel(got[:-1], signs * want[:-1])


def test_every_exact_kernel_is_mirror_symmetric():
    worst = 0.0
    for p, td in _mirror_cases(150, seed=5):
        mirror = MIRROR * td
        args = _args(p)
        stance = ek.stance(*td, *args)
        worst = max(worst, _mirrored(ek.stance(*mirror, *args), stance, MIRROR_STANCE))
        c_args, d_args = _compression_args(p), _decompression_args(p)
        down = ek.compression(*td, *c_args)
        down_m = ek.compression(*mirror, *c_args)
        worst = max(worst, _mirrored(down_m, down, MIRROR_HALF))
        if down[-1] == Status.OK:
            up = ek.decompression(*down[1:5], *d_args)
            worst = max(worst, _mirrored(ek.decompression(*down_m[1:5], *d_args), up, MIRROR_HALF))
        if stance[-1] == Status.OK:
            for t in np.linspace(0.0, 1.5 * stance[1], 7):
                worst = max(
                    worst, _mirrored(ek.state_at(t, *mirror, *args), ek.state_at(t, *td, *args), MIRROR)
                )
    # Measured over 300 such touchdowns: 0 (bitwise mirrored: every step and event is).
    assert worst < 1e-14, worst


@pytest.mark.parametrize("params", [HUMAN_RUNNER, ROBOT_HOPPER.with_(k_d=1_800.0)], ids=["human", "robot-kd"])
def test_a_vertical_hop_stays_exactly_vertical(params):
    p = params
    td = (p.q_r_td, -1.2 * math.sqrt(p.g_s * p.l0), 0.0, 0.0)
    stance = ek.stance(*td, *_args(p))
    assert stance[-1] == Status.OK
    angles = (4, 5, 8, 9)  # bottom q_th, q_thd, liftoff q_th, q_thd
    assert all(stance[i] == 0.0 for i in angles), stance
    down, up = _halves(p, td)
    assert down[-1] == up[-1] == Status.OK
    assert down[3] == down[4] == up[3] == up[4] == 0.0
    for t in np.linspace(0.0, 1.5 * stance[1], 31):
        got = ek.state_at(t, *td, *_args(p))
        assert got[-1] == Status.OK and got[2] == got[3] == 0.0, (t, got)
