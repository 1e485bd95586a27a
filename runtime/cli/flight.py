"""The exact ballistic flights every map shares (the model kernels ``apex_to_touchdown`` and
``liftoff_to_apex`` by name, :mod:`~slipmaps.runtime.api.model`; gravity ``g_f``).

:func:`touchdown` flies from an apex to touchdown with the leg held at an angle; :func:`next_apex`
from a liftoff state to the next apex. Both return a status instead of raising.
"""

from __future__ import annotations

import math

from slipmaps.generated.status import Status

from ..api import model
from ..api.params import SlipParams
from ..api.validate import PolarState

_NAN4 = (math.nan,) * 4
_POLAR = ("q_r", "q_rd", "q_th", "q_thd")


def touchdown(
    params: SlipParams, apex_height: float, apex_speed: float, angle: float, ground: float = 0.0
) -> tuple[Status, PolarState, float]:
    """(status, polar touchdown state, flight time) from the apex (height, speed), leg at ``angle``,
    on ground ``ground`` higher."""
    status, out = model.call(
        "apex_to_touchdown",
        b_y_apex=apex_height,
        b_xd_apex=apex_speed,
        q_th_td=angle,
        q_r_td=params.q_r_td,
        g_f=params.g_f,
        ground=ground,
    )
    if status != Status.OK:
        return status, _NAN4, math.nan
    return status, tuple(out[f"touchdown_{q}"] for q in _POLAR), out["t_flight"]


def direction(touchdown) -> float:
    """The direction of a step from its touchdown state: the sign of the body's horizontal velocity
    (+1 toward +x, -1 toward -x, 0 for a hop in place)."""
    _, out = model.call("polar_to_cartesian", **dict(zip(_POLAR, touchdown, strict=True)))
    xd = out["out_b_xd"]
    return float(math.copysign(1.0, xd)) if xd else 0.0


def next_apex(params: SlipParams, liftoff, direction: float) -> tuple[Status, float, float]:
    """(status, height, speed) of the apex after ``liftoff`` of a step in ``direction`` (NaN unless OK)."""
    if not all(math.isfinite(x) for x in liftoff):
        return Status.INVALID_INPUT, math.nan, math.nan
    status, out = model.call(
        "liftoff_to_apex", **dict(zip(_POLAR, liftoff, strict=True)), g_f=params.g_f, direction=direction
    )
    return status, out["apex_b_y"], out["apex_b_xd"]
