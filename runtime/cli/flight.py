"""The exact ballistic flights every map shares (generated ``flight`` kernels, gravity ``g_f``).

:func:`touchdown` flies from an apex to touchdown with the leg held at an angle; :func:`next_apex`
from a liftoff state to the next apex. Both return a status instead of raising.
"""

from __future__ import annotations

import math

from slipmaps.generated import flight as gen_flight
from slipmaps.generated import slip_model
from slipmaps.generated.status import Status

from ..api.params import SlipParams
from ..api.validate import PolarState

_NAN4 = (math.nan,) * 4


def touchdown(
    params: SlipParams, apex_height: float, apex_speed: float, angle: float, ground: float = 0.0
) -> tuple[Status, PolarState, float]:
    """(status, polar touchdown state, flight time) from the apex (height, speed), leg at ``angle``,
    on ground ``ground`` higher."""
    *state, t_flight, _, code = gen_flight.apex_to_touchdown(
        apex_height, apex_speed, angle, params.q_r_td, params.g_f, ground
    )
    status = Status(int(code))
    if status != Status.OK:
        return status, _NAN4, math.nan
    return status, tuple(float(x) for x in state), float(t_flight)


def direction(touchdown) -> float:
    """The direction of a step from its touchdown state: the sign of the body's horizontal velocity
    (+1 toward +x, -1 toward -x, 0 for a hop in place)."""
    return float(math.copysign(1.0, xd)) if (xd := slip_model.polar_to_cartesian(*touchdown)[1]) else 0.0


def next_apex(params: SlipParams, liftoff, direction: float) -> tuple[Status, float, float]:
    """(status, height, speed) of the apex after ``liftoff`` of a step in ``direction`` (NaN unless OK)."""
    if not all(math.isfinite(x) for x in liftoff):
        return Status.INVALID_INPUT, math.nan, math.nan
    h, v, _, _, _, code = gen_flight.liftoff_to_apex(*liftoff, params.g_f, direction)
    return Status(int(code)), float(h), float(v)
