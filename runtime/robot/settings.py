"""A scenario's robot plant options, read and checked: :func:`robot_settings`.

The options of ``plant = "mujoco"`` (the table ``[plant]`` beside ``kind = "mujoco"``, or
``[plant_options]``; ``slipmaps.run(..., plant="mujoco", plant_options={...})``) are the robot's
parameters (every field of :class:`~.params.RobotParams`, by name) and its terrain:

- ``terrain``: ``"ramps"`` (default: a heightfield, the levels joined by ramps) or ``"boxes"``
  (vertical steps); the levels are the scenario's touchdown grounds, one per segment
  (:class:`~.terrain.Terrain`), so a flat scenario is a plane;
- ``spacing`` [m]: the segments' length (default: :func:`step_estimate` of the start apex, so that
  a run at constant speed meets about one level per step);
- ``ramp`` [m]: the ramps' width (default 0.5, at most ``spacing``);
- ``log_rate`` [frames/s]: log each robot's trajectory at this rate for rendering (default 0: off).

Every bad value is refused with one line naming it (all of them reported, a line each).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from ..api.numeric import is_real, num
from .params import RobotParams, RobotParamsError

__all__ = ["RobotSettings", "TERRAIN_KEYS", "robot_settings", "step_estimate"]

#: The terrain and logging options, with their defaults (module docstring).
TERRAIN_KEYS = {"terrain": "ramps", "spacing": None, "ramp": 0.5, "log_rate": 0.0}
_TERRAINS = ("ramps", "boxes")


@dataclass(frozen=True)
class RobotSettings:
    """The robot plant's options: ``params`` (:class:`~.params.RobotParams`), the terrain's
    ``terrain`` kind, ``spacing`` (None: :func:`step_estimate`) and ``ramp`` [m], and ``log_rate``
    [frames/s] (0: no log)."""

    params: RobotParams
    terrain: str = "ramps"
    spacing: float | None = None
    ramp: float = 0.5
    log_rate: float = 0.0


def robot_settings(options: dict | None) -> RobotSettings:
    """The robot's settings from a scenario's plant options (module docstring); ValueError with one
    line per bad value."""
    options = dict(options or {})
    names = [f.name for f in fields(RobotParams)]
    problems = []
    unknown = sorted(set(options) - set(names) - set(TERRAIN_KEYS))
    for key in unknown:
        problems.append(
            f"plant option {key!r} is not an option of the robot; its options: "
            f"{', '.join([*TERRAIN_KEYS, *names])}"
        )
    kw = {k: options[k] for k in names if k in options}
    try:
        params = RobotParams(**kw)
    except RobotParamsError as exc:
        problems.extend(exc.problems)
        params = None
    terrain = options.get("terrain", TERRAIN_KEYS["terrain"])
    if terrain not in _TERRAINS:
        problems.append(
            f"plant option terrain must be one of {', '.join(map(repr, _TERRAINS))}, got {terrain!r}"
        )
    values = {}
    for key in ("spacing", "ramp", "log_rate"):
        x = options.get(key, TERRAIN_KEYS[key])
        if x is None:
            values[key] = None
            continue
        finite = is_real(x) and math.isfinite(x)
        if not (finite and (x >= 0 if key == "log_rate" else x > 0)):
            need = ">= 0" if key == "log_rate" else "> 0"
            problems.append(f"plant option {key} must be a finite number {need}, got {num(x)}")
        else:
            values[key] = float(x)
    if not problems and values["spacing"] is not None and values["ramp"] > values["spacing"]:
        problems.append(
            f"plant option ramp must not exceed spacing = {num(values['spacing'])} m, "
            f"got {num(values['ramp'])}"
        )
    if problems:
        raise ValueError("\n".join(problems))
    return RobotSettings(params=params, terrain=terrain, **values)


def step_estimate(params: RobotParams, apex_height: float, apex_speed: float) -> float:
    """About the distance [m] the robot travels in a step from an apex at ``apex_height`` [m] and
    ``apex_speed`` [m/s]: the speed times a flight from the apex to 0.95 l0 and back plus a
    spring-mass half period, at least l0 (a hop in place)."""
    g = params.gravity
    fall = max(apex_height - 0.95 * params.l0, 0.01)
    period = 2.0 * math.sqrt(2.0 * fall / g) + math.pi * math.sqrt(params.stance_mass / params.k_c)
    return max(params.l0, abs(apex_speed) * period)
