"""Ballistic flight events (report sections 2.1-2.2.2), solved from :func:`mechanics.ballistic_flight`.

Apex -> touchdown: the body falls from the apex (b_xd = b_xd_apex, b_yd = 0) until its height
equals ground + q_r_td cos q_th_td, the height at which a leg held at angle q_th_td and length
q_r_td touches ground ``ground`` higher than the ground under the apex (flat ground: 0). Liftoff ->
apex: the body rises until b_yd = 0; heights after liftoff are above the ground the foot stood on.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..symbols import (
    b_x,
    b_xd,
    b_xd_apex,
    b_y,
    b_y_apex,
    b_yd,
    ground,
    q_r_td,
    q_th_td,
    t,
)
from . import mechanics


@cache
def apex_to_touchdown():
    """Descent time and touchdown polar state from an apex state and a touchdown leg posture.

    Returns a dict with the time of flight ``t_flight`` (positive root of b_y(t) = ground + q_r_td
    cos q_th_td), the fall height ``drop`` that must be positive, the polar touchdown state, and
    ``foot_x``, the toe's horizontal position relative to the apex.
    """
    _, xd_t, y_t, yd_t = mechanics.ballistic_flight()
    apex = {b_xd: b_xd_apex, b_y: b_y_apex, b_yd: 0}
    y_td = mechanics.body_position(q_r_td, q_th_td)[1]
    drop = sp.Symbol("drop", positive=True)
    roots = sp.solve(sp.Eq(y_t.subs(apex), b_y_apex - drop), t)
    t_fl = [r for r in roots if r.is_positive][0]
    velocity = {b_xd: xd_t.subs(apex).subs(t, t_fl), b_yd: yd_t.subs(apex).subs(t, t_fl)}
    pos = mechanics.body_position(q_r_td, q_th_td)
    # The touchdown polar rates follow from the derived Cartesian -> polar map at the touchdown posture.
    _, rd_expr, _, thd_expr = mechanics.cartesian_to_polar()
    at_td = {b_x: pos[0], b_y: pos[1], **velocity}
    q_rd_td = sp.simplify(rd_expr.subs(at_td))
    q_thd_td = sp.simplify(thd_expr.subs(at_td))
    return {
        "drop": b_y_apex - ground - y_td,
        "t_flight": t_fl,
        "foot_x": sp.simplify(xd_t.subs(apex).subs(t, t_fl) * t_fl - pos[0]),
        "drop_symbol": drop,
        "state": (q_r_td, q_rd_td, q_th_td, q_thd_td),
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
