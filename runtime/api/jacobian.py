"""Derivatives of every map: Jacobians of the stance and of the apex-return map.

- :func:`stance_jacobian` (``name, params, touchdown``): rows are the stance outputs
  (``t_bottom``, ``t_stance``, ``bottom_*``, ``liftoff_*``, then the map's extras), columns the
  touchdown state ``q_r_td, q_rd_td, q_th_td, q_thd_td`` and the stiffness.
- :func:`apex_return_jacobian` (``name, params, apex_height, apex_speed, touchdown_angle``): rows
  are the apex-return outputs (``apex_height`` and ``apex_speed`` of the NEXT apex, the flight and
  stance times, ``liftoff_*``, extras), columns ``apex_height, apex_speed, touchdown_angle`` and
  the stiffness.
- :func:`stance_jacobian_batch`, :func:`apex_return_jacobian_batch`: the same over arrays, in
  parallel, a status per row.

The stiffness columns are the map's own parameters: ``k`` for a map that needs k_c = k_d (a change
of both together), ``k_c`` and ``k_d`` for the others and for ``"exact"``. Units: SI per unit input
(per N/m for a stiffness).

How they are computed. A generated map's Jacobian kernels are generated from its declaration by
forward-mode differentiation (``derive/tangent.py``): closed-form maps symbolically, iterative maps
through their iterations (the derivative of the iterate the map returns). ``"exact"``
differentiates the compiled simulator by the variational equations with saltation at the bottom
and the map to the liftoff surface (:mod:`.exact_jacobian`), composed with the flights' derivatives
(:mod:`.exact_step_jacobian`); ``method="scipy"`` has no Jacobian. Agreement with central
differences is measured in tests/test_jacobian.py.

Where the map is defined but a derivative is not (an infinite one, e.g. as q_rd_td -> 0), the
status is NUMERICAL_RANGE and everything NaN. With an option choice that assumes touchdown at the
rest length (``leg_length="eq21"`` ...), the ``q_r_td`` column is NaN: the map exists only at
q_r_td = l0. At q_r_td = l0 the ``q_r_td`` column is the derivative from below (q_r > l0 is not a
touchdown).
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from slipmaps.generated import maps_index
from slipmaps.generated.status import MESSAGES, Status

from ..exact import compiled as ec
from ..exact.reference import default_t_max
from .maps import _apex_rows, _Call
from .params import SlipParams
from .results import GROUPS, BatchResult, Result, columns
from .validate import leg_angle, non_negative, polar_state

__all__ = [
    "Jacobian",
    "JacobianBatch",
    "stance_jacobian",
    "stance_jacobian_batch",
    "apex_return_jacobian",
    "apex_return_jacobian_batch",
]

#: Kernel argument -> the public name of a Jacobian column.
_PUBLIC = {"b_y_apex": "apex_height", "b_xd_apex": "apex_speed", "q_th_td": "touchdown_angle"}
_TOUCHDOWN = tuple(maps_index.TOUCHDOWN)


def _indices(key: str, names: tuple[str, ...]) -> list[int]:
    """Positions of ``key`` in ``names``: a name, or a group ("bottom", "liftoff", "touchdown")."""
    if key in names:
        return [names.index(key)]
    group = _TOUCHDOWN if key == "touchdown" else GROUPS.get(key, ())
    if group and all(n in names for n in group):
        return [names.index(n) for n in group]
    raise KeyError(f"{key!r} is not among {', '.join(names)} (nor a group of them)")


def _block(matrix: np.ndarray, outputs, inputs, key):
    if not (isinstance(key, tuple) and len(key) == 2):
        raise KeyError("index a Jacobian by (output, input), e.g. jac['apex_height', 'touchdown_angle']")
    i, j = _indices(key[0], outputs), _indices(key[1], inputs)
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

    ``jac.matrix[i, j]`` is d ``outputs[i]`` / d ``inputs[j]``; ``jac["apex_height", "apex_speed"]``
    one entry, ``jac["liftoff", "touchdown"]`` a block (groups ``bottom``, ``liftoff``,
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
        return _block(self.matrix, self.outputs, self.inputs, key)


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

    def __getitem__(self, key):
        return _block(self.matrix, self.outputs, self.inputs, key)


# ----------------------------------------------------------------------------------------------
# Generated maps
# ----------------------------------------------------------------------------------------------
def _kernel(call: _Call, kind: str, batch: bool):
    jac = call.info.jacobian
    if jac is None:
        raise ValueError(f"map {call.info.name!r} has no generated Jacobian")
    module = importlib.import_module(f"slipmaps.generated.{jac['module']}")
    return getattr(module, jac[kind] + ("_batch" if batch else ""))


def _generated_names(call: _Call, kind: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    if kind == "stance":
        inputs = tuple(call.info.jacobian["stance_wrt"])
    else:
        inputs = tuple(_PUBLIC.get(w, w) for w in call.info.jacobian["apex_wrt"])
    return columns(kind, call.info.extras), inputs


def _split(row: np.ndarray, n_out: int, n_in: int) -> tuple[np.ndarray, np.ndarray]:
    """A Jacobian kernel's row: the outputs, then d output_i / d input_j row-major."""
    return row[..., :n_out], row[..., n_out : n_out + n_out * n_in].reshape(*row.shape[:-1], n_out, n_in)


# ----------------------------------------------------------------------------------------------
# "exact"
# ----------------------------------------------------------------------------------------------
def _exact_options(call: _Call) -> tuple[float, float]:
    if call.options.get("method") == "scipy":
        raise ValueError(
            "the exact Jacobian comes from the compiled simulator's variational equations; "
            "method='scipy' has none (use the default method='compiled')"
        )
    return float(call.options["rtol"]), float(call.options["atol"])


# ----------------------------------------------------------------------------------------------
# Public API
# ----------------------------------------------------------------------------------------------
def _at_rest_length(call: _Call) -> bool:
    """An option choice that assumes touchdown at the rest length (``Option.at_rest_length``): the
    map has no derivative with respect to q_r_td (it is INVALID_INPUT anywhere else)."""
    return any(call.options[o.name] in o.at_rest_length for o in call.info.options)


def _mask_rest_length(call: _Call, inputs, jac: np.ndarray) -> None:
    if "q_r_td" in inputs and _at_rest_length(call):
        jac[..., inputs.index("q_r_td")] = math.nan


def _jacobian(call: _Call, kind: str, outputs, inputs, row, jac, code, point) -> Jacobian:
    status = Status(int(code))
    if status == Status.OK and not np.isfinite(jac).all():
        status = Status.NUMERICAL_RANGE  # a derivative that does not exist there (exact path)
    if status != Status.OK:
        row = np.full(len(outputs), math.nan)
        jac = np.full((len(outputs), len(inputs)), math.nan)
    values = dict(zip(outputs, map(float, row), strict=True))
    _mask_rest_length(call, inputs, jac)
    jac.setflags(write=False)
    return Jacobian(call.info.name, kind, status, MESSAGES[int(status)], values, outputs, inputs, jac, point)


def stance_jacobian(name: str, params: SlipParams, touchdown, **options) -> Jacobian:
    """Map ``name``'s stance from the polar touchdown state and its derivatives with respect to the
    touchdown state and the stiffness (module docstring)."""
    call = _Call.of(name, params, options)
    td = polar_state(params, touchdown)
    point = {"touchdown": td, "options": dict(call.options)}
    if not call.info.generated:
        from ..exact import jacobian as ej

        rtol, atol = _exact_options(call)
        out, jac = np.empty(ej.N_OUT), np.empty((ej.N_OUT, ej.N_IN))
        code = ej.jacobian_into(
            *td, *ec.stance_args(params), params.q_r_lo, rtol, atol, default_t_max(params), out, jac
        )
        return _jacobian(call, "stance", tuple(ej.OUTPUTS), tuple(ej.INPUTS), out, jac, code, point)
    outputs, inputs = _generated_names(call, "stance")
    res = _kernel(call, "stance", False)(*td, *call.params, params.q_r_lo, *call.encoded)
    row, jac = _split(np.array(res[:-1], dtype=float), len(outputs), len(inputs))
    return _jacobian(call, "stance", outputs, inputs, row, jac.copy(), res[-1], point)


def apex_return_jacobian(
    name: str, params: SlipParams, apex_height, apex_speed, touchdown_angle, **options
) -> Jacobian:
    """One step of map ``name`` (as :func:`slipmaps.apex_return`) and its derivatives with respect to
    the apex height and speed, the touchdown angle and the stiffness (module docstring)."""
    call = _Call.of(name, params, options)
    h = non_negative("apex_height", apex_height)
    v = non_negative("apex_speed", apex_speed)
    th = leg_angle("touchdown_angle", touchdown_angle)
    point = {"apex_height": h, "apex_speed": v, "touchdown_angle": th, "options": dict(call.options)}
    if not call.info.generated:
        from ..exact import step_jacobian as esj

        rtol, atol = _exact_options(call)
        out, jac = np.empty(esj.N_OUT), np.empty((esj.N_OUT, esj.N_IN))
        code = esj.step_jacobian_into(
            h, v, th, *ec.step_args(params), rtol, atol, default_t_max(params), out, jac
        )
        return _jacobian(call, "apex_return", tuple(esj.OUTPUTS), esj.INPUTS, out, jac, code, point)
    outputs, inputs = _generated_names(call, "apex_return")
    res = _kernel(call, "apex_return", False)(
        h, v, th, *call.params, params.g_f, params.q_r_td, params.q_r_lo, *call.encoded
    )
    row, jac = _split(np.array(res[:-1], dtype=float), len(outputs), len(inputs))
    return _jacobian(call, "apex_return", outputs, inputs, row, jac.copy(), res[-1], point)


def _batch(call: _Call, kind: str, outputs, inputs, data, jac, status, shape) -> JacobianBatch:
    ok = status == int(Status.OK)
    status[ok & ~np.isfinite(jac).all(axis=(1, 2))] = int(Status.NUMERICAL_RANGE)
    bad = status != int(Status.OK)
    data[bad] = math.nan
    jac[bad] = math.nan
    _mask_rest_length(call, inputs, jac)
    jac.setflags(write=False)
    result = BatchResult(call.info.name, kind, outputs, data, status, shape)
    return JacobianBatch(
        call.info.name, kind, outputs, inputs, result, jac.reshape(*shape, len(outputs), len(inputs))
    )


def stance_jacobian_batch(name: str, params: SlipParams, touchdowns, **options) -> JacobianBatch:
    """:func:`stance_jacobian` over touchdown states of shape (n, 4), in parallel; a status per row."""
    from .maps import _rows

    call = _Call.of(name, params, options)
    arr = _rows(params, touchdowns)
    n = arr.shape[0]
    if not call.info.generated:
        from ..exact import jacobian as ej

        data, jac, status = ej.jacobian_rows(params, arr, *_exact_options(call))
        return _batch(call, "stance", tuple(ej.OUTPUTS), tuple(ej.INPUTS), data, jac, status, (n,))
    cols = tuple(np.ascontiguousarray(arr[:, j]) for j in range(4))
    status = np.empty(n, dtype=np.int64)
    outputs, inputs = _generated_names(call, "stance")
    out = np.empty((n, len(outputs) * (1 + len(inputs))))
    _kernel(call, "stance", True)(*cols, *call.params, params.q_r_lo, *call.encoded, out, status)
    data, jac = _split(out, len(outputs), len(inputs))
    return _batch(call, "stance", outputs, inputs, data.copy(), jac.copy(), status, (n,))


def apex_return_jacobian_batch(
    name: str, params: SlipParams, apex_height, apex_speed, touchdown_angle, **options
) -> JacobianBatch:
    """:func:`apex_return_jacobian` over arrays (broadcast against each other), in parallel; a
    status per row; the result has the broadcast shape."""
    call = _Call.of(name, params, options)
    flat, shape = _apex_rows(apex_height, apex_speed, touchdown_angle)
    n = int(np.prod(shape))
    status = np.empty(n, dtype=np.int64)
    if not call.info.generated:
        from ..exact import step_jacobian as esj

        rtol, atol = _exact_options(call)
        data, jac = np.empty((n, esj.N_OUT)), np.empty((n, esj.N_OUT, esj.N_IN))
        esj.step_jacobian_batch(
            *(ec.column(x) for x in flat),
            *ec.step_args(params),
            rtol,
            atol,
            default_t_max(params),
            data,
            jac,
            status,
        )
        return _batch(call, "apex_return", tuple(esj.OUTPUTS), esj.INPUTS, data, jac, status, shape)
    outputs, inputs = _generated_names(call, "apex_return")
    out = np.empty((n, len(outputs) * (1 + len(inputs))))
    extra = (params.g_f, params.q_r_td, params.q_r_lo)
    _kernel(call, "apex_return", True)(*flat, *call.params, *extra, *call.encoded, out, status)
    data, jac = _split(out, len(outputs), len(inputs))
    return _batch(call, "apex_return", outputs, inputs, data.copy(), jac.copy(), status, shape)
