"""Ballistic flight events (report sections 2.1-2.2.2), solved from :func:`mechanics.ballistic_flight`.

Apex -> touchdown: the body falls from the apex (b_xd = b_xd_apex, b_yd = 0) while the leg, at
length q_r_td, swings at ``retraction_rate`` from q_th_td, until the foot touches ground ``ground``
higher than the ground under the apex (flat ground: 0; a leg held still: b_y = ground + q_r_td cos
q_th_td). Liftoff ->
apex: the body rises until b_yd = 0; heights after liftoff are above the ground the foot stood on.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..catalog import APEX_ARGS, DIRECTION, PARAMS, POLAR, limit
from ..ir import Arg, Field, Group, Guard, Iterate, Kernel, Stage, Switch, positive, real, sym
from ..symbols import (
    b_x,
    b_xd,
    b_xd_apex,
    b_y,
    b_y_apex,
    b_yd,
    g_f,
    q_r,
    q_r_td,
    q_rd,
    q_th,
    q_th_td,
    q_thd,
    t,
)
from . import mechanics

#: The apex-return inputs (derive/params.py's rows) as kernel arguments, by name.
INPUTS = {a.name: a for a in APEX_ARGS}
#: The inputs the descent reads besides the apex and the touchdown angle: its kernel's last arguments.
DESCENT_INPUTS = ("ground", "retraction_rate")

#: Newton passes allowed for the touchdown time of a swinging leg (quadratic, monotone convergence:
#: a few passes at the rates of running; one for a leg held still).
TOUCHDOWN_PASSES = 50


@cache
def apex_to_touchdown():
    """Descent time and touchdown polar state from an apex state and a swinging leg.

    After the apex the leg angle is ``q_th(t) = q_th_td + retraction_rate * t`` (swing-leg
    retraction, Seyfarth, Geyer and Herr 2003; a rate of 0 holds the leg at ``q_th_td``) at length
    ``q_r_td``; touchdown is the time the foot meets the ground ``ground`` higher than the ground
    under the apex: the root of the foot's height above that ground,

        f(t) = b_y(t) - ground - q_r_td cos q_th(t)
             = (g_f/2) (t0 - t) (t0 + t) + q_r_td (cos q_th_td - cos q_th(t)),

    with ``t0 = sqrt(2 drop / g_f)`` the closed-form root of a leg held still (report section 2.1;
    ``drop``, the foot's height above the ground at the apex, must be positive). With
    ``|retraction_rate| <= sqrt(g_f/q_r_td)`` (3.1 rad/s for a 1 m leg; swing-leg retraction in
    running is 0.5-2 rad/s) f is concave, ``f'' = -g_f + q_r_td rate^2 cos q_th(t) <= 0``: positive at
    the apex, it has one positive root, the touchdown, and Newton's method converges to it
    monotonically from any start at or after it. The start is ``t0`` when the foot is on or below
    the ground then, else the time the body is ``q_r_td`` below the ground (where f <= 0). A leg
    held still (a rate of exactly 0) skips the iteration: its touchdown time is ``t_held``, t0 plus
    the rate times the implicit derivative -f_rate/f_t at (t0, 0), which is t0 bit for bit there (as
    Newton's method from t0 gives: the second form of f is exactly 0 at ``t = t0``) and carries the
    derivative with respect to the rate into the Jacobians.

    Returns a dict: ``drop`` (an expression), ``t0``, ``t_held``; ``residual`` and ``slope`` (f and
    df/dt at the symbol ``t``); ``angle`` (q_th at ``t``); the polar touchdown ``state`` and ``foot_x`` (the
    toe's horizontal position relative to the apex) at the time ``t`` and the angle symbol
    ``angle_symbol``; ``t_far``, the time the body is ``q_r_td`` below the contact height (in
    ``drop_symbol``), Newton's start when the foot is still above the ground at ``t0``.
    """
    ground, rate = INPUTS["ground"].symbol, INPUTS["retraction_rate"].symbol
    # the height, above the ground under the apex, at which the foot touches down
    contact = ground
    # the leg angle a time t after the apex
    angle = q_th_td + rate * t
    x_t, xd_t, y_t, yd_t = mechanics.ballistic_flight()
    apex = {b_x: 0, b_xd: b_xd_apex, b_y: b_y_apex, b_yd: 0}
    drop = b_y_apex - contact - mechanics.body_position(q_r_td, q_th_td)[1]
    drop_symbol = sp.Symbol("drop", positive=True)
    t0 = [r for r in sp.solve(sp.Eq(y_t.subs(apex), b_y_apex - drop_symbol), t) if r.is_positive][0]
    t0_symbol = sp.Symbol("t0", positive=True)
    # Newton's start when the swinging foot is still above the ground at t0: the time the body is
    # q_r_td below the contact height (every foot is on or below the ground then); the contact
    # height in drop: b_y_apex - drop - q_r_td cos q_th_td
    below = b_y_apex - drop_symbol - mechanics.body_position(q_r_td, q_th_td)[1] - q_r_td
    (root,) = [r for r in sp.solve(sp.Eq(y_t.subs(apex), below), t) if not r.could_extract_minus_sign()]
    g_flight = -sp.sympify(y_t.subs(apex)).diff(t, 2)
    # as sqrt(2 drop + 2 q_r_td cos q_th_td + 2 q_r_td) / sqrt(g_f): one square root of the sum
    t_far = sp.sqrt(sp.expand(root**2 * g_flight)) / sp.sqrt(g_flight)
    g = sp.sympify(y_t.subs(apex)).diff(t, 2) * -1  # the flight gravity, from the derived flight
    residual = g / 2 * (t0_symbol - t) * (t0_symbol + t) + q_r_td * (sp.cos(q_th_td) - sp.cos(angle))
    check = sp.simplify(
        (y_t.subs(apex) - contact - mechanics.body_position(q_r_td, angle)[1]).subs(drop_symbol, drop)
        - residual.subs(t0_symbol, t0).subs(drop_symbol, drop)
    )
    if check != 0:
        raise AssertionError(f"apex_to_touchdown: the residual's two forms differ by {check}")
    # a leg held still (rate 0): the closed form t0, with its first-order term in the rate (the
    # implicit derivative -f_rate/f_t at (t0, 0)): t0 itself at a rate of 0, and the derivative of the
    # touchdown time with respect to the rate there
    t_held = t0_symbol - rate * sp.simplify(
        (residual.diff(rate) / residual.diff(t)).subs({t: t0_symbol, rate: 0})
    )
    th = sp.Symbol("touchdown_angle", real=True)
    pos = mechanics.body_position(q_r_td, th)
    # The touchdown polar rates follow from the derived Cartesian -> polar map at the touchdown posture.
    _, rd_expr, _, thd_expr = mechanics.cartesian_to_polar()
    at_td = {b_x: pos[0], b_y: pos[1], b_xd: xd_t.subs(apex), b_yd: yd_t.subs(apex)}
    return {
        "drop": drop,
        "drop_symbol": drop_symbol,
        "t0": t0,
        "t0_symbol": t0_symbol,
        "t_far": t_far,
        "t_held": t_held,
        "residual": residual,
        "slope": residual.diff(t),
        "angle": angle,
        "angle_symbol": th,
        "foot_x": sp.simplify(x_t.subs(apex) - pos[0]),
        "state": (q_r_td, sp.simplify(rd_expr.subs(at_td)), th, sp.simplify(thd_expr.subs(at_td))),
    }


@cache
def liftoff_to_apex():
    """Next apex (height, speed), rise time and horizontal travel from a liftoff state.

    The apex quantities are in the Cartesian liftoff state (b_x, b_xd, b_y, b_yd), which
    ``liftoff_cartesian`` gives from the polar one.
    """
    x_t, xd_t, y_t, yd_t = mechanics.ballistic_flight()
    t_apex = sp.solve(sp.Eq(yd_t, 0), t)[0]
    return {
        "liftoff_cartesian": mechanics.polar_to_cartesian(),
        "t_flight": t_apex,
        "b_y_apex": sp.simplify(y_t.subs(t, t_apex)),
        "b_xd_apex": xd_t.subs(t, t_apex),
        "dx_flight": sp.simplify((x_t - b_x).subs(t, t_apex)),
        "apex_b_x": sp.simplify(x_t.subs(t, t_apex)),
    }


#: Liftoff with a horizontal speed against the step's direction by more than BACKWARD_TOLERANCE *
#: sqrt(g_f q_r) is backward (the body reversed in the stance); a hop in place (direction 0) may lift
#: off either way.
BACKWARD_TOLERANCE = 1e-9


@cache
def flight_kernels() -> dict[str, Kernel]:
    """Ballistic flight between apex and stance events (exact in every apex-return map), by name."""
    atd = apex_to_touchdown()
    drop, t0, angle = atd["drop_symbol"], atd["t0_symbol"], atd["angle_symbol"]
    t_td, slope, t_far, t_start = sym("t_td"), sym("foot_slope"), sym("t_far"), sym("t_start")
    rate, swinging = INPUTS["retraction_rate"].symbol, sym("swinging")
    at = {t: t_td}
    q_r_td = PARAMS["q_r_td"].symbol
    # the touchdown angle's sine and cosine, set by each branch of the touchdown time (a leg held
    # still reuses those of q_th_td: two trigonometric calls fewer on the common path)
    sin_td, cos_td = sym("sin_td"), sym("cos_td")
    trig = {sp.sin(angle): sin_td, sp.cos(angle): cos_td}
    # a swinging leg's touchdown time: Newton's method from a start at or after it
    newton = (
        Stage(
            (
                (t_far, atd["t_far"]),
                (
                    t_start,
                    sp.Piecewise((t0, atd["residual"].subs(t, t0) <= 0), (t_far, True)),
                ),
            ),
            comment="a start at or after the touchdown: t0 if the foot is on or below the ground then, "
            "else the time the body is q_r_td below the ground",
        ),
        Iterate(
            state=((t_td, t_start),),
            evaluate=(
                Stage(
                    ((slope, atd["slope"].subs(at)),),
                    (
                        Guard(
                            slope < 0,
                            "NO_TOUCHDOWN",
                            "the foot descends toward the ground",
                        ),
                    ),
                ),
            ),
            body=(),
            update=(t_td - atd["residual"].subs(at) / slope,),
            max_iter=sp.Integer(TOUCHDOWN_PASSES),
            tol=sp.Float(1e-12),
            scales=(t0,),
            count=sym("touchdown_passes"),
            fail_status="NOT_CONVERGED",
            comment="Newton's method on the foot's height (concave: monotone from the right)",
        ),
        Stage(
            (
                (angle, atd["angle"].subs(at)),
                (sin_td, sp.sin(angle)),
                (cos_td, sp.cos(angle)),
            ),
            comment="the leg angle at touchdown, its sine and cosine",
        ),
    )
    apex_to_td = Kernel(
        name="apex_to_touchdown",
        summary="Ballistic descent from an apex to touchdown with the leg at q_r_td swinging from q_th_td at "
        "retraction_rate.",
        equations=("sec2.1-touchdown", "sec2.2.2"),
        args=(
            APEX_ARGS[0],
            Arg(b_xd_apex, "horizontal apex speed [m/s], signed"),
            APEX_ARGS[2],
            Arg(q_r_td, "touchdown leg length [m], > 0", positive(q_r_td)),  # l0 is not an argument here
            PARAMS["g_f"],
            *(INPUTS[name] for name in DESCENT_INPUTS),
        ),
        steps=(
            Stage(
                ((drop, atd["drop"]),),
                (Guard(real(drop) > 0, "APEX_TOO_LOW", "the foot above the touchdown ground at the apex"),),
            ),
            Stage(
                ((t0, atd["t0"]),),
                (limit("retraction_rate"),),  # |rate| <= sqrt(g_f/q_r_td) (derive/params.py's row)
                comment="the descent time of a leg held still (section 2.1)",
            ),
            Stage(
                ((swinging, sp.Piecewise((0, sp.Eq(rate, 0)), (1, True))),),
                comment="0: the leg held still (retraction_rate = 0), 1: a swinging leg",
            ),
            Switch(
                swinging,
                (
                    (
                        0,
                        (
                            Stage(
                                (
                                    (t_td, atd["t_held"]),
                                    (t_start, t0),
                                    (t_far, t0),
                                    (slope, atd["slope"].subs({t: t0, rate: 0})),
                                    (sym("touchdown_passes"), sp.Integer(0)),
                                    (angle, atd["angle"].subs(at)),
                                    (sin_td, sp.sin(q_th_td) + rate * t0 * sp.cos(q_th_td)),
                                    (cos_td, sp.cos(q_th_td) - rate * t0 * sp.sin(q_th_td)),
                                ),
                                comment="t0 with its first-order term in the rate (its derivative; the rate "
                                "is 0 here, so the values are t0 and q_th_td's, as Newton's method from t0 "
                                "gives bit for bit); no pass; the touchdown angle's sine and cosine: those "
                                "of q_th_td",
                                zero=(rate,),
                            ),
                        ),
                    ),
                    (
                        1,
                        newton,
                    ),
                ),
                comment="the touchdown time: closed form for a leg held still, else Newton's method",
            ),
            Stage(
                (),
                (Guard(sp.Abs(angle) < sp.pi / 2, "NO_TOUCHDOWN", "the leg above the horizontal"),),
            ),
            Stage(
                tuple(
                    zip(
                        (
                            sym(n)
                            for n in ("touchdown_q_r", "touchdown_q_rd", "touchdown_q_th", "touchdown_q_thd")
                        ),
                        (e.subs(at).subs(trig) for e in atd["state"]),
                        strict=True,
                    )
                )
                + ((sym("t_flight"), t_td), (sym("foot_x"), atd["foot_x"].subs(at).subs(trig))),
                comment="touchdown state from the derived Cartesian -> polar map",
            ),
        ),
        outputs=Group(
            "",
            (
                Group("touchdown", POLAR, "polar state at touchdown"),
                Field("t_flight", "time from the apex to touchdown", "s"),
                Field(
                    "foot_x",
                    "horizontal position of the toe at touchdown relative to the apex",
                    "m",
                    odd=True,
                ),
            ),
        ),
        module="flight",
    )
    lta = liftoff_to_apex()
    cart = tuple(zip((b_x, b_xd, b_y, b_yd), lta["liftoff_cartesian"], strict=True))
    lo_to_apex = Kernel(
        name="liftoff_to_apex",
        summary="Ballistic ascent from a polar liftoff state to the next apex.",
        equations=("sec2.1-apex", "sec2.2.2"),
        args=(
            Arg(q_r, "liftoff leg length q_r [m], > 0", positive(q_r)),
            Arg(q_rd, "leg length rate q_rd [m/s]"),
            Arg(q_th, "leg angle q_th from the vertical, counterclockwise positive [rad]"),
            Arg(q_thd, "leg angle rate q_thd [rad/s]"),
            PARAMS["g_f"],
            DIRECTION,
        ),
        steps=(
            Stage(
                cart,
                (
                    Guard(b_yd > 0, "LIFTOFF_DOWNWARD", "liftoff requires an upward velocity"),
                    Guard(
                        DIRECTION.symbol * b_xd >= -BACKWARD_TOLERANCE * sp.sqrt(real(g_f) * real(q_r)),
                        "LIFTOFF_BACKWARD",
                        "the body must not move against the step's direction (a hop in place: either way)",
                    ),
                ),
                comment="Cartesian liftoff state relative to the toe",
            ),
            Stage(
                (
                    (sym("apex_b_y"), lta["b_y_apex"]),
                    (sym("apex_b_xd"), lta["b_xd_apex"]),
                    (sym("t_flight"), lta["t_flight"]),
                    (sym("dx_flight"), lta["dx_flight"]),
                    (sym("apex_b_x"), lta["apex_b_x"]),
                ),
                comment="apex where b_yd(t) = 0",
            ),
        ),
        outputs=Group(
            "",
            (
                Field("apex_b_y", "next apex height above the ground", "m"),
                Field("apex_b_xd", "next apex horizontal speed", "m/s", odd=True),
                Field("t_flight", "time from liftoff to the apex", "s"),
                Field("dx_flight", "horizontal distance travelled from liftoff to the apex", "m", odd=True),
                Field("apex_b_x", "horizontal position of the next apex relative to the toe", "m", odd=True),
            ),
        ),
        module="flight",
    )
    return {"apex_to_touchdown": apex_to_td, "liftoff_to_apex": lo_to_apex}
