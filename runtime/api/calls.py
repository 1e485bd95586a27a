"""One calling convention: a map call's arguments are filled by name from the generated index.

A :class:`Call` is a map, its parameters and its options, validated once (cached, so a controller
calling a map thousands of times with the same ones pays the Python checks once). It holds every
kernel argument the parameters and options give, by name (:attr:`Call.values`: ``m``, ``l0``,
``k_c``, ``k_d`` and ``k`` when they agree, ``g_s``, ``g_f``, ``q_r_td``, ``q_r_lo``, each kernel
option), the backend that runs the map, and each role's kernel (for an option with kernels per
choice, ``specialize`` in the index, the kernel of the call's choice):

- :class:`KernelBackend`: the generated kernels. A role's :class:`~.index.KernelSpec` (from the
  index) lists its arguments; :meth:`KernelBackend.scalar` passes ``{**call.values, **inputs}`` in
  that order, :meth:`KernelBackend.rows` the row arrays and the shared scalars in the batch form's
  order. Nothing here knows a kernel's argument order, and no function branches on a map's name:
  the exact map is generated like the others.
- an option choice naming a module (the index's ``backends``; the exact map's ``method="scipy"``:
  :mod:`slipmaps.runtime.exact.reference`) runs the map through that module's ``BACKEND``, which
  has the same two methods.

Per-call inputs are given by kernel argument name too: the touchdown state ``q_r_td, q_rd_td,
q_th_td, q_thd_td`` (it replaces the parameter ``q_r_td`` in a stance), the apex ``b_y_apex,
b_xd_apex, q_th_td, ground``, a time ``t``, a half's start state.
"""

from __future__ import annotations

import importlib
import math
import operator
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cache, lru_cache
from typing import Protocol

import numpy as np
from slipmaps.generated.status import Status

from . import memory
from .batch import BatchInterrupted, run_rows
from .index import MapInfo, get, get_half
from .params import SlipParams

__all__ = ["Backend", "Call", "KernelBackend", "KERNELS", "column_count", "row_bytes"]


def column_count(call: Call, role: str) -> int:
    """The number of columns a role's batch writes: its outputs, and for a Jacobian d output /
    d input for every (output, input) pair after them."""
    return call.spec(role).width


def row_bytes(spec) -> int:
    """The bytes a batch of a role kernel allocates per row, at most: its outputs (a Jacobian's
    derivatives included) and its status, its input row, and a copy of each input (an input
    broadcast against the others is copied to one value per row)."""
    return 8 * (spec.width + 1 + 2 * len(spec.x))


class Backend(Protocol):
    """What runs a map: a role (``stance``, ``apex_return``, ``state_at``, ``half``,
    ``stance_jacobian``, ``apex_return_jacobian``) once or over rows; failures are statuses."""

    def scalar(self, call: Call, role: str, inputs: Mapping[str, float]) -> tuple[float, ...]:
        """The role's outputs as Python floats (a Jacobian's: values, then row-major derivatives)
        and the status."""

    def rows(
        self, call: Call, role: str, rows: Mapping[str, np.ndarray], inputs: Mapping[str, float], n: int, show
    ) -> tuple[np.ndarray, np.ndarray]:
        """``(out (n, columns), status (n,))`` over ``n`` rows: ``rows`` holds the per-row inputs
        (1-D float arrays), ``inputs`` the per-call ones; ``show`` a progress bar (None: auto).
        Ctrl-C: :class:`~.batch.BatchInterrupted` whose ``result`` is ``(out, status)`` of the
        rows finished."""


class KernelBackend:
    """The generated role kernels, their ``x`` and ``p`` filled by name (the index's layouts)."""

    def scalar(self, call: Call, role: str, inputs: Mapping[str, float]) -> tuple[float, ...]:
        plan = ScalarPlan.get(call, role)
        out = np.empty(plan.width)
        status = plan.run(inputs, out)
        return (*out.tolist(), status)

    def rows(self, call, role, rows, inputs, n, show):
        spec = call.spec(role)
        out = np.empty((n, spec.width))
        status = np.empty(n, dtype=np.int64)
        if n == 1 and spec.record_only.isdisjoint(rows):
            # one row: the row kernel, as a scalar call makes it (the batch form's arrays cost more)
            one = dict(inputs)
            for a, x in rows.items():
                one[a] = x[0]
            status[0] = ScalarPlan.get(call, role).run(one, out[0])
            return out, status
        try:
            run_rows(
                kernel_functions(spec)[1],
                *layout_rows(spec, call.record(spec, rows=True), rows, inputs, n),
                out,
                status,
            )
        except BatchInterrupted as stop:
            stop.result = (out[: stop.done], status[: stop.done])
            raise
        return out, status


@dataclass(frozen=True)
class ScalarPlan:
    """A role's scalar call as :class:`KernelBackend` makes it, resolved once per :class:`Call`
    (a controller's thousands of calls look up the spec, the kernel and the record once): the row
    kernel, its parameter record ``p``, the length of ``out``, and ``take``, which gives the
    role's inputs ``x`` from a mapping by name in the layout's order."""

    kernel: Callable
    record: np.ndarray
    width: int
    take: Callable[[Mapping[str, float]], tuple[float, ...]]

    @classmethod
    def get(cls, call: Call, role: str) -> ScalarPlan:
        """The call's plan for the role (made on its first use)."""
        plan = call._scalars.get(role)
        if plan is None:
            plan = call._scalars[role] = cls.of(call, role)
        return plan

    @classmethod
    def of(cls, call: Call, role: str) -> ScalarPlan:
        spec = call.spec(role)
        if len(spec.x) == 1:  # itemgetter of one name gives the value, not a tuple
            (name,) = spec.x

            def take(inputs):
                return (inputs[name],)
        else:
            take = operator.itemgetter(*spec.x)
        return cls(kernel_functions(spec)[0], call.record(spec), spec.width, take)

    def run(self, inputs: Mapping[str, float], out: np.ndarray) -> int:
        """The kernel on ``inputs`` (by name), writing ``out`` (``width`` floats): its status."""
        return self.kernel(np.array(self.take(inputs), np.float64), self.record, out)


class Columns(dict):
    """Per-row inputs that are the columns of one (n, k) float64 ``matrix``, in the order of
    ``names``: a dict of column views by name, whose matrix :func:`layout_rows` hands as it is to a
    role kernel whose inputs ``x`` are those names in that order (a batch of stance states)."""

    def __init__(self, matrix: np.ndarray, names) -> None:
        self.names = tuple(names)
        super().__init__((a, matrix[:, j]) for j, a in enumerate(self.names))
        self.matrix = matrix


def layout_rows(spec, record: np.ndarray, rows: Mapping, inputs: Mapping, n: int):
    """``(X, P)`` of ``n`` rows of a role kernel: ``X`` (n, len(x)) its inputs by name from the
    per-row arrays ``rows`` or the per-call ``inputs``; ``P`` the parameter ``record`` as a (1, k)
    array (``Call.record(spec, rows=True)`` is handed on as it is; a 1-D record is viewed so), or
    one per row (n, k) when ``rows`` also holds a parameter (a plant's stiffness per run). A record
    field that is also an input (the stance's touchdown leg length ``q_r_td``) is not one: a role
    kernel reads it from ``x`` (derive/lower.py unpacks from ``p`` only the names ``x`` lacks)."""
    if record.ndim == 1:
        record = record[None, :]
    if isinstance(rows, Columns) and rows.names == tuple(spec.x):
        X = np.ascontiguousarray(rows.matrix, dtype=np.float64)  # read only by the kernel
    elif n == 1:  # one row from a list: a column assignment per input costs more than the row
        X = np.array([[float(rows[a][0]) if a in rows else inputs[a] for a in spec.x]])
    else:
        X = np.empty((n, len(spec.x)))
        for j, a in enumerate(spec.x):
            X[:, j] = rows[a] if a in rows else inputs[a]
    varying = [f for f in rows if f in spec.record_only]
    if not varying:
        return X, record
    P = np.repeat(record, n, axis=0)
    for f in varying:
        P[:, spec.p.index(f)] = rows[f]
    return X, P


#: The generated kernels' backend (stateless).
KERNELS = KernelBackend()
#: A status code -> its Status (a dict lookup; ``Status(code)`` costs about 0.7 us a call).
_STATUS = {int(s): s for s in Status}


_FUNCTIONS: dict = {}


def kernel_functions(spec):
    """(row kernel, batch form) of a role kernel spec, imported once (by module and name: a spec's
    own hash would hash its name tuples on every call)."""
    key = (spec.module, spec.name)
    functions = _FUNCTIONS.get(key)
    if functions is None:
        functions = _FUNCTIONS[key] = spec.functions()
    return functions


@cache
def _backend_module(module: str) -> Backend:
    return importlib.import_module(module).BACKEND


@dataclass(frozen=True)
class Call:
    """A map, its parameters and its options, validated once per call (module docstring)."""

    info: MapInfo
    params: SlipParams
    options: Mapping[str, object]  # the resolved options, by name
    values: Mapping[str, float]  # every kernel argument the parameters and options give, by name
    backend: Backend
    #: Every role's kernel for these options (the kernel of the choice of a specialized option).
    kernels: Mapping[str, object]
    #: The parameter records built (:meth:`record`), by layout.
    _records: dict = field(default_factory=dict, compare=False, repr=False)
    #: The roles' scalar calls resolved (:class:`ScalarPlan`), by role.
    _scalars: dict = field(default_factory=dict, compare=False, repr=False)

    @classmethod
    def of(cls, name: str, params: SlipParams, options: dict, half: bool = False) -> Call:
        """Validated once per (map, parameters, options); ``half``: a half-stance map. ValueError
        naming an unknown map or option, or a requirement the parameters break."""
        try:
            key = (name, params, tuple(sorted(options.items())) if options else (), half)
            hash(key)
        except TypeError:  # an unhashable option value: validate (and refuse) it uncached
            return cls._build(name, params, options, half)
        return cls._cached(key)

    @staticmethod
    @lru_cache(maxsize=256)
    def _cached(key) -> Call:
        name, params, options, half = key
        return Call._build(name, params, dict(options), half)

    @classmethod
    def _build(cls, name: str, params: SlipParams, options: dict, half: bool = False) -> Call:
        info = get_half(name) if half else get(name)
        info.check_params(params)
        resolved = info.resolve(options)
        values = {**params.values(), **info.encode(resolved)}  # ValueError naming the valid values
        module = info.backend(resolved)
        backend = KERNELS if module is None else _backend_module(module)
        if hasattr(backend, "check_params"):  # a backend that does not model every parameter
            backend.check_params(params)
        return cls(info, params, resolved, values, backend, info.kernels_for(resolved))

    def record(self, spec, rows: bool = False) -> np.ndarray:
        """The parameter record ``p`` of a role kernel (the map's parameters and kernel options by
        the index's names; one per call, shared by its roles); ``rows``: as the (1, k) ``P`` of its
        batch form."""
        records = self._records.get(spec.p)
        if records is None:
            # writable, as every array a kernel is given (numba compiles a read-only one apart)
            record = np.array([self.values.get(f, math.nan) for f in spec.p], dtype=np.float64)
            records = self._records[spec.p] = (record, record[None, :])
        return records[rows]

    def spec(self, role: str):
        """The role's kernel spec; ValueError when the map has none (naming the maps that have one)."""
        spec = self.kernels.get(role)
        if spec is None:
            raise ValueError(f"map {self.info.name!r} has no {role.replace('_', ' ')} kernel")
        return spec

    def scalar(self, role: str, inputs: Mapping[str, float]) -> tuple[Status, tuple[float, ...], str | None]:
        """``(status, outputs, message)`` of one call of the role; the message is the backend's own
        when it has a more specific one than the status's (the solve_ivp reference names the stage
        and event that failed), else None."""
        res = self.backend.scalar(self, role, inputs)
        return _STATUS[int(res[-1])], res[:-1], getattr(res, "message", None)

    def rows(self, role: str, rows: Mapping[str, np.ndarray], inputs: Mapping[str, float], n: int, show=None):
        """``(out, status)`` of the role over ``n`` rows (:meth:`Backend.rows`)."""
        if n == 0:
            return np.empty((0, column_count(self, role))), np.empty(0, dtype=np.int64)
        return self.backend.rows(self, role, rows, inputs, n, show)

    def check_memory(self, role: str, n: int) -> int:
        """The bytes a batch of ``n`` rows of the role allocates (:func:`row_bytes`); ValueError,
        one line with the estimate, when they exceed the machine's available memory
        (:func:`.memory.check`)."""
        need = n * row_bytes(self.spec(role))
        if need < memory.SMALL:  # the message not even formatted: a small batch's call stays short
            return need
        return memory.check(
            need,
            f"a batch of {n:,} rows ({self.info.name} {role}) needs",
            "give fewer rows, or split them into several batches",
        )

    def batch(self, role: str, rows, inputs, shape: tuple[int, ...], make, show=None, given=None):
        """``make(call, role, out, status, shape, given)`` of the role over the rows of ``shape``
        (:meth:`rows`; the caller checked their memory, :meth:`check_memory`, before copying any),
        ``given`` the inputs by name (each broadcasting to ``shape``) the result carries. Ctrl-C:
        :class:`~.batch.BatchInterrupted` whose ``result`` is ``make`` of the rows finished (shape
        ``(done,)``, their inputs cut to those rows)."""
        try:
            out, status = self.rows(role, rows, inputs, math.prod(shape), show)
        except BatchInterrupted as stop:
            if stop.result is not None:
                out, status = stop.result
                done = stop.done
                cut = None
                if given is not None:
                    flat = {
                        k: np.broadcast_to(np.asarray(v, dtype=float), shape).reshape(-1)
                        for k, v in given.items()
                    }
                    cut = {k: v[:done] for k, v in flat.items()}
                stop.result = make(self, role, out, status, (done,), cut)
            raise
        return make(self, role, out, status, shape, given)
