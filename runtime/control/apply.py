"""A deadbeat plan applied: the step of a map (the exact map by default: the plant) with the plan's
controls.

:func:`apply_plan` (also :meth:`DeadbeatResult.apply <slipmaps.DeadbeatResult.apply>`) steps map
``map`` from the apex the plan is for (its ``inputs``: ``apex_height``, ``apex_speed``, ``ground``,
``retraction_rate``) with the plan's ``touchdown_angle`` and its ``k_c`` and ``k_d`` as the step's
stiffness, and returns that map's :class:`~slipmaps.Result` (:func:`slipmaps.apex_return`): its
``next_apex_height``, ``next_apex_speed`` are where the plan lands on that map. The parameters are
the plan's (the model's) unless ``params`` gives the plant's own (a mass mismatch, ...), their
stiffness replaced by the plan's. A constant-stiffness map (``geyer``, the gravity corrections)
takes a plan whose k_c equals its k_d (else the ValueError of its requirement). A plan that is
UNREACHABLE applies its closest controls; one that is MAP_FAILED has none (ValueError).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..api.index import EXACT
from ..api.maps import apex_return
from ..api.params import SlipParams
from ..api.results import Result

if TYPE_CHECKING:
    from .deadbeat import DeadbeatResult

__all__ = ["apply_plan"]


def apply_plan(
    plan: DeadbeatResult,
    map: str = EXACT,  # noqa: A002 - the map's name, as every map call's first argument
    params: SlipParams | None = None,
    **options,
) -> Result:
    """The step of map ``map`` (default ``"exact"``) with ``plan``'s controls (module docstring):
    ``params`` the plant's parameters (default: the plan's), ``options`` the map's."""
    if not plan.ok:
        raise ValueError(
            f"apply_plan: plan has status {plan.status} ({plan.map_status.name}): the map failed at every "
            "control the solve tried, so it has no controls to apply"
        )
    base = plan.params if params is None else params
    if not isinstance(base, SlipParams):
        raise TypeError(f"params must be a SlipParams, got {type(base).__name__}")
    stiffness = base.with_(k_c=plan.k_c, k_d=plan.k_d)
    return apex_return(map, stiffness, touchdown_angle=plan.touchdown_angle, **plan.inputs, **options)
