"""The default step of ``slipmaps compare`` (and :func:`slipmaps.runtime.cli.compare.compare`), scaled
with the leg so that any parameter set gets a comparable step.

Apex height in units of the rest leg length l0, apex speed as a Froude number ``v / sqrt(g_f l0)``
(flight gravity ``g_f``), and the touchdown angle (rad from the vertical, counterclockwise positive)
scaled by the dimensionless stiffness ``kappa = k_c l0 / (m g_s)``: the stance sweeps an angle of
about (stance time pi sqrt(m/k)) x (angular rate v/l0) = pi Fr / sqrt(kappa), so a leg softer than
the human runner's (kappa 25.5) gets a flatter touchdown angle, ``TOUCHDOWN_ANGLE *
sqrt(kappa_human / kappa)``. The constants are chosen so that the human runner (l0 = 1 m, g = 9.81
m/s^2, kappa 25.5) keeps exactly its documented step, 1.0 m at 5 m/s with the leg at 0.35 rad; the
robot hopper (l0 = 0.25 m, kappa 12.7) gets 0.25 m at 2.5 m/s and 0.495 rad. Imports no generated
module, so the command line can show the defaults in ``--help`` without the kernels.
"""

from __future__ import annotations

import math

from ..api.params import HUMAN_RUNNER, SlipParams
from ..api.validate import non_negative, positive

__all__ = [
    "APEX_HEIGHT_L0",
    "APEX_FROUDE",
    "TOUCHDOWN_ANGLE",
    "apex_height_of",
    "apex_speed_of",
    "default_touchdown_angle",
    "default_apex",
    "stiffness_number",
]

#: The default apex height in units of l0 (1.0 m for the human runner).
APEX_HEIGHT_L0 = 1.0
#: The default apex speed as a Froude number v / sqrt(g_f l0): 5 / sqrt(9.81) = 1.596, so 5 m/s for
#: the human runner and 2.5 m/s for a 0.25 m leg.
APEX_FROUDE = 5.0 / math.sqrt(9.81)
#: The human runner's default touchdown leg angle [rad] (about 20 deg); other legs scale it by
#: sqrt(kappa_human / kappa) (:func:`default_touchdown_angle`).
TOUCHDOWN_ANGLE = 0.35


def stiffness_number(params: SlipParams) -> float:
    """The dimensionless compression stiffness kappa = k_c l0 / (m g_s) (25.5 for the human runner)."""
    return params.k_c * params.l0 / (params.m * params.g_s)


def apex_height_of(params: SlipParams, height_l0: float) -> float:
    """The apex height [m] of a height given in units of l0."""
    return positive("apex height in units of l0", height_l0) * params.l0


def apex_speed_of(params: SlipParams, froude: float) -> float:
    """The apex speed [m/s] of a Froude number ``v / sqrt(g_f l0)``."""
    return non_negative("apex Froude number", froude) * math.sqrt(params.g_f * params.l0)


def default_touchdown_angle(params: SlipParams) -> float:
    """The default touchdown angle [rad]: TOUCHDOWN_ANGLE sqrt(kappa_human / kappa), exactly
    TOUCHDOWN_ANGLE for the human runner's kappa (the ratio of equal numbers is 1.0)."""
    return TOUCHDOWN_ANGLE * math.sqrt(stiffness_number(HUMAN_RUNNER) / stiffness_number(params))


def default_apex(params: SlipParams) -> dict[str, float]:
    """The default step for ``params``: ``apex_height`` = APEX_HEIGHT_L0 l0 [m], ``apex_speed`` =
    APEX_FROUDE sqrt(g_f l0) [m/s], ``touchdown_angle`` = :func:`default_touchdown_angle` [rad]."""
    return {
        "apex_height": apex_height_of(params, APEX_HEIGHT_L0),
        "apex_speed": apex_speed_of(params, APEX_FROUDE),
        "touchdown_angle": default_touchdown_angle(params),
    }
