"""Property tests of the generated kernels' contract and of the Python layer's input validation.

Kernel contract (derive/kernel.py): a kernel never raises; it returns its outputs plus a status
code, and either the status is OK (0) and every output is finite, or the status names the first
failed guard and every output is NaN. Invalid inputs (non-finite, nonpositive parameters, a leg at
or below the horizontal, a leg longer than l0) give INVALID_INPUT; a touchdown that is not
compressing gives TOUCHDOWN_NOT_COMPRESSING.

The Python layer (slipmaps.runtime) validates before calling a kernel: a bad argument is a
ValueError that names the offending value, and valid inputs never raise.

"Garbage" inputs mix NaN, +-inf, zeros, negatives and magnitudes in [MIN_MAGNITUDE, MAX_MAGNITUDE]
(1e-300 .. 1e300): kernels compile with error_model="numpy" and end with an all-outputs-finite
guard (NUMERICAL_RANGE), so overflow, underflow and cancellation are statuses, not exceptions. The
``test_regression_*`` tests at the end pin the cases that used to break the contract.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from slipmaps.generated import flight as g_flight
from slipmaps.generated import geyer as g_geyer
from slipmaps.generated.status import Status
from slipmaps.runtime.apex_maps import apex_return_geyer
from slipmaps.runtime.params import SlipParams
from slipmaps.runtime.stance_maps import geyer_stance

HALF_PI = math.pi / 2
MAX_MAGNITUDE = 1e300
MIN_MAGNITUDE = 1e-300
NAN, INF = math.nan, math.inf

SETTINGS = settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])

#: name -> (kernel, argument names)
KERNELS = {
    "geyer_stance": (
        g_geyer.geyer_stance,
        ("q_r_td", "q_rd_td", "q_th_td", "q_thd_td", "m", "l0", "k", "g_s", "q_r_lo"),
    ),
    "geyer_stance_state_at": (
        g_geyer.geyer_stance_state_at,
        ("t", "q_r_td", "q_rd_td", "q_th_td", "q_thd_td", "m", "l0", "k", "g_s"),
    ),
    "apex_to_touchdown": (g_flight.apex_to_touchdown, ("b_y_apex", "b_xd_apex", "q_th_td", "q_r_td", "g_f")),
    "liftoff_to_apex": (g_flight.liftoff_to_apex, ("q_r", "q_rd", "q_th", "q_thd", "g_f")),
    "geyer_apex_return": (
        g_geyer.geyer_apex_return,
        ("b_y_apex", "b_xd_apex", "q_th_td", "m", "l0", "k", "g_s", "g_f", "q_r_td", "q_r_lo"),
    ),
}
N_OUT = {
    "geyer_stance": 10,
    "geyer_stance_state_at": 4,
    "apex_to_touchdown": 5,
    "liftoff_to_apex": 4,
    "geyer_apex_return": 9,
}


def assert_status_contract(name, res):
    assert isinstance(res, tuple) and len(res) == N_OUT[name] + 1, res
    status, out = res[-1], res[:-1]
    assert status in set(Status), f"{name}: unknown status {status!r}"
    if status == Status.OK:
        assert all(math.isfinite(x) for x in out), f"{name}: non-finite output with status OK: {res}"
    else:
        assert all(math.isnan(x) for x in out), f"{name}: status {Status(status).name} with non-NaN {res}"
    return Status(status)


# ----------------------------------------------------------------------------------------------
# Strategies
# ----------------------------------------------------------------------------------------------
SPECIALS = (
    NAN,
    INF,
    -INF,
    0.0,
    -0.0,
    -1.0,
    1.0,
    HALF_PI,
    -HALF_PI,
    MAX_MAGNITUDE,
    -MAX_MAGNITUDE,
    MIN_MAGNITUDE,
)


def garbage():
    """Anything a caller might pass: non-finite, zero, negative, small or huge values.

    Finite values are 0 or have magnitudes in [MIN_MAGNITUDE, MAX_MAGNITUDE] (see the module
    docstring for what breaks outside).
    """
    return st.one_of(
        st.sampled_from(SPECIALS),
        st.floats(MIN_MAGNITUDE, MAX_MAGNITUDE),
        st.floats(-MAX_MAGNITUDE, -MIN_MAGNITUDE),
        st.floats(0.05, 5.0),  # plausible magnitudes, so that later guards are reached too
        st.floats(-5.0, -0.05),
    )


@st.composite
def params(draw):
    """SLIP parameters over a wide physical range (dimensionless stiffness 2-60)."""
    m = draw(st.floats(0.5, 150.0))
    l0 = draw(st.floats(0.1, 1.5))
    g_s = draw(st.floats(1.0, 25.0))
    kappa = draw(st.floats(2.0, 60.0))
    return {"m": m, "l0": l0, "k": kappa * m * g_s / l0, "g_s": g_s, "g_f": draw(st.floats(1.0, 25.0))}


@st.composite
def touchdown(draw, compressing=True, at_rest_length=False):
    """A valid touchdown state plus parameters (all inputs of geyer_stance and geyer_stance_state_at).

    ``compressing``: q_rd_td < 0 (True), q_rd_td >= 0 (False) or either (None).
    """
    if compressing is None:
        compressing = draw(st.booleans())
    p = draw(params())
    l0, scale = p["l0"], math.sqrt(p["g_s"] * p["l0"])
    p["q_r_td"] = l0 if at_rest_length else l0 * draw(st.one_of(st.just(1.0), st.floats(0.7, 1.0)))
    p["q_r_lo"] = l0 if at_rest_length else l0 * draw(st.one_of(st.just(1.0), st.floats(0.7, 1.0)))
    if compressing:
        p["q_rd_td"] = -scale * draw(st.floats(0.02, 3.0))
    else:
        p["q_rd_td"] = scale * draw(st.one_of(st.just(0.0), st.floats(0.0, 3.0)))
    p["q_th_td"] = draw(st.floats(-1.5, 1.5))
    p["q_thd_td"] = math.sqrt(p["g_s"] / l0) * draw(st.floats(-3.0, 3.0))
    p["t"] = draw(st.floats(0.0, 2.0)) * math.sqrt(p["m"] / p["k"])
    return p


@st.composite
def apex(draw):
    """A valid apex state plus parameters (all inputs of the flight kernels and geyer_apex_return)."""
    p = draw(params())
    l0 = p["l0"]
    p["q_r_td"] = l0 * draw(st.one_of(st.just(1.0), st.floats(0.7, 1.0)))
    p["q_r_lo"] = l0 * draw(st.one_of(st.just(1.0), st.floats(0.7, 1.0)))
    p["b_y_apex"] = l0 * draw(st.floats(0.05, 3.0))
    p["b_xd_apex"] = math.sqrt(p["g_f"] * l0) * draw(st.floats(0.0, 4.0))
    p["q_th_td"] = draw(st.floats(-1.5, 1.5))
    p.update(
        q_r=p["q_r_lo"], q_rd=draw(st.floats(-5.0, 5.0)), q_th=p["q_th_td"], q_thd=draw(st.floats(-15, 15))
    )
    return p


def _call(name, env):
    kern, names = KERNELS[name]
    return kern(*(env[n] for n in names))


# ----------------------------------------------------------------------------------------------
# The status contract
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", list(KERNELS))
@SETTINGS
@given(data=st.data())
def test_garbage_never_raises_and_keeps_status_contract(name, data):
    kern, names = KERNELS[name]
    args = [data.draw(garbage(), label=n) for n in names]
    assert_status_contract(name, kern(*args))


@pytest.mark.parametrize("name", ["geyer_stance", "geyer_stance_state_at"])
@SETTINGS
@given(env=touchdown())
def test_valid_touchdown_keeps_status_contract(name, env):
    status = assert_status_contract(name, _call(name, env))
    assert status not in (Status.INVALID_INPUT, Status.TOUCHDOWN_NOT_COMPRESSING)


@pytest.mark.parametrize("name", ["apex_to_touchdown", "liftoff_to_apex", "geyer_apex_return"])
@SETTINGS
@given(env=apex())
def test_valid_apex_and_liftoff_keep_status_contract(name, env):
    status = assert_status_contract(name, _call(name, env))
    assert status != Status.INVALID_INPUT


#: Per kernel: argument -> the kinds of invalid value it rejects (besides NaN and +-inf, which every
#: argument rejects). "nonpositive": <= 0; "above_l0": > l0; "angle": |x| >= pi/2.
INVALID_KINDS = {
    "geyer_stance": {
        **dict.fromkeys(("m", "l0", "k", "g_s"), ("nonpositive",)),
        "q_r_td": ("nonpositive", "above_l0"),
        "q_r_lo": ("nonpositive", "above_l0"),
        "q_th_td": ("angle",),
    },
    "geyer_stance_state_at": {
        **dict.fromkeys(("m", "l0", "k", "g_s"), ("nonpositive",)),
        "q_r_td": ("nonpositive", "above_l0"),
        "q_th_td": ("angle",),
    },
    "apex_to_touchdown": {
        **dict.fromkeys(("q_r_td", "g_f"), ("nonpositive",)),
        "b_y_apex": ("negative",),
        "q_th_td": ("angle",),
    },
    "liftoff_to_apex": dict.fromkeys(("q_r", "g_f"), ("nonpositive",)),
    "geyer_apex_return": {
        **dict.fromkeys(("m", "l0", "k", "g_s", "g_f"), ("nonpositive",)),
        "b_y_apex": ("negative",),
        "q_r_td": ("nonpositive", "above_l0"),
        "q_r_lo": ("nonpositive", "above_l0"),
        "q_th_td": ("angle",),
    },
}


@st.composite
def valid_inputs(draw, name):
    if name in ("geyer_stance", "geyer_stance_state_at"):
        return draw(touchdown(compressing=None))
    env = draw(apex())
    if name == "geyer_apex_return":
        # High enough that a too-long touchdown leg (up to 2 l0) still touches down: the stance
        # kernel, not the flight, must see the invalid input.
        env["b_y_apex"] = env["l0"] * draw(st.floats(2.05, 3.0))
    return env


@pytest.mark.parametrize("name", list(KERNELS))
@SETTINGS
@given(data=st.data())
def test_invalid_input_status(name, data):
    env = data.draw(valid_inputs(name), label="valid inputs")
    _, names = KERNELS[name]
    arg = data.draw(st.sampled_from(names), label="corrupted argument")
    kinds = ("nonfinite", *INVALID_KINDS[name].get(arg, ()))
    kind = data.draw(st.sampled_from(kinds), label="kind")
    if kind == "nonfinite":
        bad = data.draw(st.sampled_from((NAN, INF, -INF)))
    elif kind == "nonpositive":
        bad = data.draw(st.one_of(st.sampled_from((0.0, -0.0)), st.floats(-MAX_MAGNITUDE, 0.0)))
    elif kind == "negative":
        bad = -data.draw(st.floats(MIN_MAGNITUDE, MAX_MAGNITUDE))
    elif kind == "above_l0":
        bad = env["l0"] * (1.0 + data.draw(st.floats(1e-9, 1.0)))
    else:
        bad = math.copysign(data.draw(st.floats(HALF_PI, 1e3)), data.draw(st.sampled_from((1.0, -1.0))))
    res = _call(name, {**env, arg: bad})
    assert assert_status_contract(name, res) == Status.INVALID_INPUT, f"{arg}={bad!r} -> {res}"


@pytest.mark.parametrize("name", ["geyer_stance", "geyer_stance_state_at"])
@SETTINGS
@given(env=touchdown(compressing=False))
def test_not_compressing_touchdown(name, env):
    res = _call(name, env)
    assert assert_status_contract(name, res) == Status.TOUCHDOWN_NOT_COMPRESSING


@SETTINGS
@given(env=touchdown())
def test_stance_event_order(env):
    """Touchdown, bottom, liftoff in this order; the bottom is the shortest leg of the stance."""
    res = _call("geyer_stance", env)
    assume(res[-1] == Status.OK)
    t_bottom, t_stance = res[0], res[1]
    assert 0.0 <= t_bottom <= t_stance and t_stance > 0.0
    assert res[2] <= min(env["q_r_td"], res[6]) * (1 + 1e-12)
    assert res[6] == pytest.approx(env["q_r_lo"], rel=1e-12)


@SETTINGS
@given(env=touchdown(at_rest_length=True))
def test_eq26_bottom_time_branch(env):
    """Eq (26), corrected: touchdown and liftoff at l0 give 0 < t_b = t_s / 2 < t_s, slow and fast gaits.

    t_b = atan2(|q_rd_td| w, q_thd_td^2 l0 - g_s) / w with w = sqrt(k/m + 3 q_thd_td^2); the printed
    arctan form is negative for slow gaits (q_thd_td^2 l0 < g_s), which the kernel must not follow.
    The kernel computes t_b = (asin(s_td) + pi/2) / w from the squared amplitude b^2, a difference of
    energies of order k l0^2 / m that leaves only q_rd_td^2: its relative error grows like
    (k l0 / (m g_s)) (g_s l0 / q_rd_td^2) eps, up to 60 * 2500 * 2.2e-16 = 3e-11 with the strategy's
    bounds (measured worst 2.9e-11 over 2e5 samples), hence rel=1e-9. t_b = t_s / 2 holds to
    rounding (bitwise in practice).
    """
    res = _call("geyer_stance", env)
    assume(res[-1] == Status.OK)
    t_bottom, t_stance = res[0], res[1]
    assert 0.0 < t_bottom < t_stance
    assert t_bottom == pytest.approx(t_stance / 2, rel=1e-12)
    w = math.sqrt(env["k"] / env["m"] + 3 * env["q_thd_td"] ** 2)
    slope = env["q_thd_td"] ** 2 * env["l0"] - env["g_s"]
    assert t_bottom == pytest.approx(math.atan2(abs(env["q_rd_td"]) * w, slope) / w, rel=1e-9)


# ----------------------------------------------------------------------------------------------
# The Python layer
# ----------------------------------------------------------------------------------------------
def _slip(env, **extra):
    return SlipParams(
        m=env["m"],
        l0=env["l0"],
        k_c=env["k"],
        k_d=env["k"],
        g_s=env["g_s"],
        g_f=env["g_f"],
        q_r_td=env["q_r_td"],
        q_r_lo=env["q_r_lo"],
        **extra,
    )


def _mentions(message: str, value: float) -> bool:
    return repr(float(value)) in message


@SETTINGS
@given(env=touchdown(compressing=None))
def test_python_geyer_stance_valid_never_raises(env):
    res = geyer_stance(_slip(env), (env["q_r_td"], env["q_rd_td"], env["q_th_td"], env["q_thd_td"]))
    assert isinstance(res.status, Status) and res.message
    if res.ok:
        assert all(math.isfinite(x) for x in (*res.bottom, *res.liftoff, res.t_bottom, res.t_stance))


@SETTINGS
@given(env=apex())
def test_python_apex_return_valid_never_raises(env):
    res = apex_return_geyer(_slip(env), env["b_y_apex"], env["b_xd_apex"], env["q_th_td"])
    assert isinstance(res.status, Status) and res.message
    if res.ok:
        assert all(math.isfinite(x) for x in (*res.next_apex, res.t_descent, res.t_stance, res.t_ascent))


@SETTINGS
@given(data=st.data())
def test_python_geyer_stance_rejects_bad_touchdown(data):
    env = data.draw(touchdown())
    state = [env["q_r_td"], env["q_rd_td"], env["q_th_td"], env["q_thd_td"]]
    i = data.draw(st.integers(0, 3), label="component")
    choices = [st.sampled_from((NAN, INF, -INF))]
    if i == 0:
        choices += [st.floats(-10.0, 0.0), st.floats(env["l0"] * (1 + 1e-9), 10.0)]
    if i == 2:
        choices += [st.floats(HALF_PI, 10.0), st.floats(-10.0, -HALF_PI)]
    bad = data.draw(st.one_of(*choices), label="bad value")
    state[i] = bad
    with pytest.raises(ValueError) as exc:
        geyer_stance(_slip(env), state)
    msg = str(exc.value)
    assert ("q_r", "q_rd", "q_th", "q_thd")[i] in msg
    assert _mentions(msg, bad), msg


@SETTINGS
@given(data=st.data())
def test_python_apex_return_rejects_bad_apex(data):
    env = data.draw(apex())
    args = {"apex_height": env["b_y_apex"], "apex_speed": env["b_xd_apex"], "q_th_td": env["q_th_td"]}
    name = data.draw(st.sampled_from(list(args)), label="argument")
    choices = [st.sampled_from((NAN, INF, -INF))]
    if name == "apex_height":
        choices.append(st.floats(-10.0, -1e-12))  # 0 is valid: APEX_TOO_LOW, as in the simulator
    elif name == "apex_speed":
        choices.append(st.floats(-10.0, -1e-12))
    else:
        choices += [st.floats(HALF_PI, 10.0), st.floats(-10.0, -HALF_PI)]
    bad = data.draw(st.one_of(*choices), label="bad value")
    args[name] = bad
    with pytest.raises(ValueError) as exc:
        apex_return_geyer(_slip(env), *args.values())
    msg = str(exc.value)
    assert name in msg and _mentions(msg, bad), msg


def test_slip_params_negative_mass():
    with pytest.raises(ValueError, match=r"SlipParams\.m .*-1\b"):
        SlipParams(m=-1)


@SETTINGS
@given(
    field=st.sampled_from(["m", "l0", "k_c", "k_d", "g_s", "g_f", "q_r_td", "q_r_lo"]),
    bad=st.one_of(st.sampled_from((NAN, INF, -INF, 0.0, -0.0)), st.floats(-1e6, 0.0)),
)
def test_slip_params_reject_bad_values(field, bad):
    with pytest.raises(ValueError) as exc:
        SlipParams(**{field: bad})
    msg = str(exc.value)
    assert f"SlipParams.{field}" in msg and _mentions(msg, bad), msg


@SETTINGS
@given(field=st.sampled_from(["q_r_td", "q_r_lo"]), excess=st.floats(1e-9, 10.0))
def test_slip_params_reject_leg_longer_than_l0(field, excess):
    bad = 1.0 + excess
    with pytest.raises(ValueError) as exc:
        SlipParams(l0=1.0, **{field: bad})
    assert field in str(exc.value) and _mentions(str(exc.value), bad)


# ----------------------------------------------------------------------------------------------
# Regressions: cases that used to raise or report non-finite outputs as OK
def test_regression_leg_collapse_is_a_fall():
    # k/m = 16 = 2 g_s + q_rd_td^2 with q_thd_td = 0: the approximate bottom leg length
    # l0 (1 + a - b) is exactly 0 (it used to divide by zero in b_q_thd = omega / 0**2).
    res = g_geyer.geyer_stance(1.0, -2.0, 0.0, 0.0, 0.5, 1.0, 8.0, 6.0, 1.0)
    assert assert_status_contract("geyer_stance", res) == Status.FALL


def test_regression_negative_bottom_leg_length_is_a_fall():
    # Soft leg (k = 5 kN/m), hard landing (q_rd_td = -8 m/s): the approximate leg would pass through
    # the toe (bottom q_r = -0.13 m); it used to be reported OK.
    res = g_geyer.geyer_stance(1.0, -8.0, 0.1, -1.0, 80.0, 1.0, 5000.0, 9.81, 1.0)
    assert assert_status_contract("geyer_stance", res) == Status.FALL


@pytest.mark.parametrize("name", ["geyer_stance", "geyer_stance_state_at"])
def test_regression_underflow_is_a_status(name):
    # omega0^2 = k/m underflows to 0; it used to raise ZeroDivisionError.
    env = {"t": 0.1, "q_r_td": 1.0, "q_rd_td": -0.5, "q_th_td": 0.3, "q_thd_td": 0.0}
    env.update(m=1e300, l0=1.0, k=1e-300, g_s=9.81, q_r_lo=1.0)
    assert assert_status_contract(name, _call(name, env)) != Status.OK


@pytest.mark.parametrize(
    ("name", "args"),
    [
        ("liftoff_to_apex", (1.0, 1e200, -0.1, 0.0, 9.81)),
        ("apex_to_touchdown", (1.0, 1e300, 0.3, 1e-10, 9.81)),
        # q_rd_td = -1e200 m/s: the approximate leg collapses through the toe before anything overflows
        pytest.param(
            "geyer_stance_state_at",
            (0.1, 1.0, -1e200, 0.3, -3.0, 80.0, 1.0, 20000.0, 9.81),
            marks=pytest.mark.fall,
            id="state_at-collapse",
        ),
        ("geyer_stance_state_at", (1e308, 1.0, -0.5, 0.3, -3.0, 80.0, 1.0, 20000.0, 9.81)),
    ],
)
def test_regression_overflow_is_numerical_range(name, args, request):
    # These used to return inf / NaN outputs with status OK.
    expected = Status.FALL if request.node.get_closest_marker("fall") else Status.NUMERICAL_RANGE
    assert assert_status_contract(name, KERNELS[name][0](*args)) == expected
