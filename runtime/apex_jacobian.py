"""The Jacobian of the apex-return map for the gait search: ``slipmaps.apex_return_jacobian`` when the
package has it, else a central-difference stand-in of the same shape.

:func:`apex_jacobian` is the one entry point of :mod:`.gait`. The stand-in,
:class:`CentralDifference`, has the attributes of the public Jacobian result: ``status``, ``ok``,
``message``, ``result`` (the :func:`~slipmaps.runtime.maps.apex_return` result at the point),
``outputs`` (``("apex_height", "apex_speed")``), ``inputs`` (``("apex_height", "apex_speed",
"touchdown_angle")``), ``matrix`` (shape ``(len(outputs), len(inputs))``) and ``jr[output, input]``
(a float), so the gait code reads a derivative by names only and switches to the exact derivatives
without a change once ``slipmaps.apex_return_jacobian`` exists.

The step: :data:`STEP` (absolute, in m, m/s and rad) for every input, measured on the human runner's
fixed point at apex height 1 m and 5 m/s (touchdown angle 0.411 rad): for the exact simulator and
for ``geyer``, ``gravity-type5`` and ``iterative`` the central differences with steps 3e-5 to 1e-6
agree to 1e-9 of the derivative (e.g. exact d h'/d h: 0.6032523221, 0.6032523247, 0.6032523251,
0.6032523249 at 3e-5, 1e-5, 3e-6, 1e-6); at 1e-2 the truncation error is 5e-4 and below 1e-7 the
exact simulator's round-off shows (0.6032523037). At 1e-5 the truncation error is about 5e-10.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import slipmaps
from slipmaps.generated.status import MESSAGES, Status

from .maps import apex_return
from .params import SlipParams
from .results import Result

__all__ = ["STEP", "OUTPUTS", "INPUTS", "CentralDifference", "apex_jacobian", "central_difference"]

#: The central-difference step of every input (m, m/s, rad): see the module docstring.
STEP = 1e-5
#: Differentiated outputs (the next apex) and inputs (this apex and the leg angle), by result name.
OUTPUTS = ("apex_height", "apex_speed")
INPUTS = ("apex_height", "apex_speed", "touchdown_angle")


@dataclass(frozen=True)
class CentralDifference:
    """The apex-return Jacobian by central differences, in the shape of the public Jacobian result."""

    status: Status
    message: str
    result: Result
    matrix: np.ndarray  # (len(outputs), len(inputs)); NaN unless ok
    outputs: tuple[str, ...] = OUTPUTS
    inputs: tuple[str, ...] = INPUTS

    @property
    def ok(self) -> bool:
        return self.status == Status.OK

    def __getitem__(self, key: tuple[str, str]) -> float:
        out, inp = key
        if out not in self.outputs or inp not in self.inputs:
            raise KeyError(
                f"no derivative d {out} / d {inp}; outputs {', '.join(self.outputs)}, "
                f"inputs {', '.join(self.inputs)}"
            )
        return float(self.matrix[self.outputs.index(out), self.inputs.index(inp)])


def central_difference(
    name: str, params: SlipParams, apex_height, apex_speed, touchdown_angle, *, step: float = STEP, **options
) -> CentralDifference:
    """d(next apex height, speed) / d(apex height, speed, touchdown angle) of map ``name`` by central
    differences with ``step``; the status is the first failed step's (the point's own first)."""
    x = {"apex_height": apex_height, "apex_speed": apex_speed, "touchdown_angle": touchdown_angle}
    center = apex_return(name, params, **x, **options)
    matrix = np.full((len(OUTPUTS), len(INPUTS)), np.nan)
    status = center.status
    if center.ok:
        for j, key in enumerate(INPUTS):
            plus = apex_return(name, params, **{**x, key: x[key] + step}, **options)
            minus = apex_return(name, params, **{**x, key: x[key] - step}, **options)
            bad = next((r for r in (plus, minus) if not r.ok), None)
            if bad is not None:
                status = bad.status
                matrix[:] = np.nan
                break
            for i, out in enumerate(OUTPUTS):
                matrix[i, j] = (plus[out] - minus[out]) / (2.0 * step)
    message = MESSAGES[int(status)] + ("" if status == center.status else " (at a difference step)")
    return CentralDifference(Status(int(status)), message, center, matrix)


def apex_jacobian(name: str, params: SlipParams, apex_height, apex_speed, touchdown_angle, **options):
    """The apex-return Jacobian of map ``name`` at one point: ``slipmaps.apex_return_jacobian`` where
    the package provides it, else :func:`central_difference`."""
    if hasattr(slipmaps, "apex_return_jacobian"):
        return slipmaps.apex_return_jacobian(
            name, params, apex_height, apex_speed, touchdown_angle, **options
        )
    return central_difference(name, params, apex_height, apex_speed, touchdown_angle, **options)
