"""Derivatives of every map: Jacobians of the stance and of the apex-return map.

- :func:`stance_jacobian` (``name, params, touchdown``): rows are the stance outputs
  (``t_bottom``, ``t_stance``, ``bottom_*``, ``liftoff_*``, then the map's extras), columns the
  touchdown state ``q_r_td, q_rd_td, q_th_td, q_thd_td`` and the stiffness.
- :func:`apex_return_jacobian` (``name, params, apex_height, apex_speed, touchdown_angle,
  ground=, retraction_rate=``): rows are the apex-return outputs (the next apex
  ``next_apex_height``, ``next_apex_speed``, the flight and stance times, ``liftoff_*``, ``step_length``,
  ``foot_x``, ``foot_y``, ``touchdown_q_th``, extras), columns the apex-return inputs
  (derive/params.py: ``apex_height, apex_speed, touchdown_angle, ground, retraction_rate``) and
  the stiffness.
- :func:`stance_jacobian_batch`, :func:`apex_return_jacobian_batch`: the same over arrays, in
  parallel, a status per row.

The stiffness columns are the map's own parameters: ``k`` for a map that needs k_c = k_d (a change
of both together), ``k_c`` and ``k_d`` for the others and for ``"exact"``. Units: SI per unit input
(per N/m for a stiffness).

How they are computed. Every map's Jacobian kernels are generated from its declaration by
forward-mode differentiation (``derive/tangent.py``): closed-form maps symbolically, iterative maps
through their iterations (the derivative of the iterate the map returns), and the exact map
through its stance's own Jacobian (the compiled simulator's variational equations with saltation
at the bottom and the map to the liftoff surface, ``generated/exact_stance.py``), composed with
the flights' derivatives like every map's; ``method="scipy"`` has no Jacobian. They are called
like the maps, arguments by name (:mod:`.calls`). Agreement with central differences is measured in
tests/test_jacobian.py.

Where the map is defined but a derivative is not (an infinite one, e.g. as q_rd_td -> 0), the
status is NUMERICAL_RANGE and everything NaN. With an option choice that assumes touchdown at the
rest length (``leg_length="eq21"`` ...), the ``q_r_td`` column is NaN: the map exists only at
q_r_td = l0. At q_r_td = l0 the ``q_r_td`` column is the derivative from below (q_r > l0 is not a
touchdown).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from slipmaps.generated import maps_index
from slipmaps.generated.status import MESSAGES, Status

from .calls import Call, Columns
from .frames import to_arrow, to_pandas
from .inputs import apex_signature
from .maps import apex_inputs, apex_rows, state_rows, touchdown_inputs
from .params import SlipParams
from .results import GROUPS, BatchResult, Result, renamed
from .validate import outside_limits, polar_state

__all__ = [
    "Jacobian",
    "JacobianBatch",
    "stance_jacobian",
    "stance_jacobian_batch",
    "apex_return_jacobian",
    "apex_return_jacobian_batch",
]

#: Kernel argument -> the public name of a Jacobian column (the apex-return inputs' API names).
_PUBLIC = dict(maps_index.APEX_PUBLIC)
_TOUCHDOWN = tuple(maps_index.TOUCHDOWN)


def _indices(key: str, names: tuple[str, ...]) -> list[int]:
    """Positions of ``key`` in ``names``: a name, or a group ("bottom", "liftoff", "touchdown")."""
    if key in names:
        return [names.index(key)]
    group = _TOUCHDOWN if key == "touchdown" else GROUPS.get(key, ())
    if group and all(n in names for n in group):
        return [names.index(n) for n in group]
    raise KeyError(f"{key!r} is not among {', '.join(names)} (nor a group of them)")


def _block(matrix: np.ndarray, outputs, inputs, key, kind: str):
    if not (isinstance(key, tuple) and len(key) == 2):
        raise KeyError("index a Jacobian by (output, input), e.g. jac['next_apex_height', 'touchdown_angle']")
    output = key[0] if key[0] in outputs else renamed(key[0], outputs, kind, 3) or key[0]
    i, j = _indices(output, outputs), _indices(key[1], inputs)
    block = matrix[..., i, :][..., j]
    if len(i) == 1 and len(j) == 1:
        return block[..., 0, 0] if block.ndim > 2 else float(block[0, 0])
    if len(i) == 1:
        return block[..., 0, :]
    if len(j) == 1:
        return block[..., 0]
    return block


@dataclass(frozen=True)
class Jacobian:
    """One map's outputs and their derivatives at one point.

    ``jac.matrix[i, j]`` is d ``outputs[i]`` / d ``inputs[j]``; ``jac["next_apex_height",
    "apex_speed"]`` one entry, ``jac["liftoff", "touchdown"]`` a block (groups ``bottom``, ``liftoff``,
    ``touchdown``). ``jac.result`` is the map's :class:`~.results.Result` at the point (the values
    are those of ``slipmaps.stance`` / ``slipmaps.apex_return`` to round-off). NaN unless OK.
    """

    map: str
    kind: str  # "stance" or "apex_return"
    status: Status
    message: str
    values: Mapping[str, float]
    outputs: tuple[str, ...]
    inputs: tuple[str, ...]
    matrix: np.ndarray = field(repr=False)
    point: Mapping[str, object] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.status == Status.OK

    @property
    def result(self) -> Result:
        return Result(self.map, self.kind, self.status, self.message, dict(self.values), dict(self.point))

    def __getitem__(self, key):
        return _block(self.matrix, self.outputs, self.inputs, key, self.kind)


@dataclass(frozen=True)
class JacobianBatch:
    """Jacobians over many points: ``result`` is the :class:`~.results.BatchResult` of the values,
    ``matrix`` has shape ``(*result.shape, len(outputs), len(inputs))`` (NaN in rows that are not
    OK), ``jac[output, input]`` an array in the inputs' shape (or a block)."""

    map: str
    kind: str
    outputs: tuple[str, ...]
    inputs: tuple[str, ...]
    result: BatchResult
    matrix: np.ndarray = field(repr=False)

    @property
    def status(self) -> np.ndarray:
        return self.result["status"]

    @property
    def ok(self) -> np.ndarray:
        return self.result.ok

    def counts(self) -> dict[str, int]:
        """Rows per status name, most common first (as :meth:`BatchResult.counts`)."""
        return self.result.counts()

    def columns(self) -> dict[str, np.ndarray]:
        """The values' columns (:meth:`BatchResult.columns`), then a column per derivative named
        ``d(output)/d(input)``, a row per point (``slipmaps.runtime.api.frames``)."""
        out = self.result.columns()
        m = self.matrix.reshape(-1, len(self.outputs), len(self.inputs))
        for a, o in enumerate(self.outputs):
            for b, i in enumerate(self.inputs):
                out[f"d({o})/d({i})"] = m[:, a, b]
        return out

    def to_pandas(self):
        """A pandas DataFrame of :meth:`columns`."""
        return to_pandas(self.columns())

    def to_arrow(self):
        """A pyarrow Table of :meth:`columns`."""
        return to_arrow(self.columns())

    def __getitem__(self, key):
        return _block(self.matrix, self.outputs, self.inputs, key, self.kind)


# ----------------------------------------------------------------------------------------------
# Every map: the role's kernel (values, then d output_i / d input_j row-major), by name
# ----------------------------------------------------------------------------------------------
def _names(call: Call, role: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(outputs, inputs) of a Jacobian: its rows and its columns, by their public names (the next
    apex ``next_apex_height`` ..., :mod:`.names`; the apex-return inputs' API names)."""
    spec = call.spec(role)
    wrt = tuple(_PUBLIC.get(w, w) for w in spec.wrt) if role == "apex_return_jacobian" else spec.wrt
    return spec.public_outputs, wrt


def _split(row: np.ndarray, n_out: int, n_in: int) -> tuple[np.ndarray, np.ndarray]:
    """A Jacobian kernel's row: the outputs, then d output_i / d input_j row-major."""
    return row[..., :n_out], row[..., n_out : n_out + n_out * n_in].reshape(*row.shape[:-1], n_out, n_in)


def _at_rest_length(call: Call) -> bool:
    """An option choice that assumes touchdown at the rest length (``Option.at_rest_length``): the
    map has no derivative with respect to q_r_td (it is INVALID_INPUT anywhere else)."""
    return any(call.options[o.name] in o.at_rest_length for o in call.info.options)


def _mask_rest_length(call: Call, inputs, jac: np.ndarray) -> None:
    if "q_r_td" in inputs and _at_rest_length(call):
        jac[..., inputs.index("q_r_td")] = math.nan


def _jacobian(call: Call, role: str, status: Status, row, point, message: str | None = None) -> Jacobian:
    outputs, inputs = _names(call, role)
    values, jac = _split(np.array(row, dtype=float), len(outputs), len(inputs))
    jac = jac.copy()
    if status == Status.OK and not np.isfinite(jac).all():
        status = Status.NUMERICAL_RANGE  # a derivative that does not exist there
    if status != Status.OK:
        values = np.full(len(outputs), math.nan)
        jac = np.full((len(outputs), len(inputs)), math.nan)
    _mask_rest_length(call, inputs, jac)
    jac.setflags(write=False)
    kind = role.removesuffix("_jacobian")
    named = dict(zip(outputs, map(float, values), strict=True))
    message = message if message and status != Status.OK else MESSAGES[int(status)]
    return Jacobian(call.info.name, kind, status, message, named, outputs, inputs, jac, point)


def stance_jacobian(name: str, params: SlipParams, touchdown, **options) -> Jacobian:
    """Map ``name``'s stance from the polar touchdown state and its derivatives with respect to the
    touchdown state and the stiffness (module docstring)."""
    call = Call.of(name, params, options)
    td = polar_state(params, touchdown)
    status, row, _ = call.scalar("stance_jacobian", touchdown_inputs(call, td))
    return _jacobian(call, "stance_jacobian", status, row, {"touchdown": td, "options": dict(call.options)})


@apex_signature
def apex_return_jacobian(name: str, params: SlipParams, given: dict, **options) -> Jacobian:
    """One step of map ``name`` (as :func:`slipmaps.apex_return`) and its derivatives with respect to
    the apex height and speed, the touchdown angle, the ground and the stiffness (module docstring)."""
    call = Call.of(name, params, options)
    inputs, point = apex_inputs(given)
    status, row, message = call.scalar("apex_return_jacobian", inputs)
    if status == Status.INVALID_INPUT and message is None:  # an input outside its range: which
        message = outside_limits(params, point)
    point["options"] = dict(call.options)
    return _jacobian(call, "apex_return_jacobian", status, row, point, message)


def _batch(call: Call, role: str, out: np.ndarray, status: np.ndarray, shape, given) -> JacobianBatch:
    """The batch's values and Jacobians as views of the kernel's ``out`` (no copy of the wide
    output): the batch kernels already report a row whose derivative is not finite as
    NUMERICAL_RANGE with NaN everywhere (derive/templates/kernels.py.j2), and a failed row is NaN."""
    outputs, inputs = _names(call, role)
    data, jac = _split(out, len(outputs), len(inputs))
    _mask_rest_length(call, inputs, jac)
    jac.setflags(write=False)
    kind = role.removesuffix("_jacobian")
    result = BatchResult(call.info.name, kind, outputs, data, status, shape, given)
    return JacobianBatch(
        call.info.name, kind, outputs, inputs, result, jac.reshape(*shape, len(outputs), len(inputs))
    )


def stance_jacobian_batch(name: str, params: SlipParams, touchdowns, **options) -> JacobianBatch:
    """:func:`stance_jacobian` over touchdown states of shape (n, 4), in parallel; a status per row.
    Its memory need is checked first; Ctrl-C raises :class:`~slipmaps.BatchInterrupted` with the
    rows finished."""
    call = Call.of(name, params, options)
    arr = state_rows(params, touchdowns, call=call, role="stance_jacobian")
    td = Columns(arr, call.spec("stance_jacobian").x)
    return call.batch("stance_jacobian", td, {}, arr.shape[:1], _batch, given=td)


@apex_signature
def apex_return_jacobian_batch(name: str, params: SlipParams, given: dict, **options) -> JacobianBatch:
    """:func:`apex_return_jacobian` over arrays (broadcast against each other), in parallel; a
    status per row; the result has the broadcast shape. Its memory need is checked before any row
    is copied; Ctrl-C raises :class:`~slipmaps.BatchInterrupted` with the rows finished."""
    call = Call.of(name, params, options)
    rows, inputs, shape = apex_rows(given, call, "apex_return_jacobian")
    return call.batch("apex_return_jacobian", rows, inputs, shape, _batch, given=given)
