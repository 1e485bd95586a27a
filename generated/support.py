# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/templates/support.py.j2
# Template:  derive/templates/support.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""What the generated kernels share, owned by the generator (derive/templates/support.py.j2): arrays
on a kernel's stack, a row's store and its checks.

- ``carray(stack(n), n)``: an array of ``n`` float64 (``n`` a literal integer) in the stack frame of
  the kernel that writes it: the arguments and outputs a kernel passes through an array (a role
  kernel's ``x``, ``p`` and ``out``, a call with more than 16 of them; derive/lower.py) cost no
  allocation. Valid until that kernel returns; never returned or kept.
- ``row(A, i)``: row ``i`` of a 2-D float64 array as a 1-D array that borrows ``A``'s memory, without
  a reference count: what a batch form hands its role kernel for ``X[i]`` and ``OUT[i]`` (an
  ``A[i]`` view increments and decrements ``A``'s count, atomically, on every row). Valid while
  ``A`` is: never returned or kept. A batch form copies each parameter record ``P[b]`` into a
  ``carray(stack(k), k)`` that the rows of that record read (every row, for one record): no store
  into ``OUT`` can change the copy, so what the kernel computes from the record alone (its checks,
  ``1/l0``, ``k/m`` ...) is computed once per record, not per row (Geyer's stance on one thread:
  47 -> 43 ns a row; the hand-written kernel of benchmarks/ checks its parameters once too).
- ``fail(out, status)``: ``out`` all NaN; returns ``status`` (a failed row).
- ``into_rows``: numba's inline cost model of a role kernel: its body is inlined into its own batch
  form only.
- ``finite(out)``: every entry of ``out`` finite.
- ``store(a, (v0, v1, ...))`` and ``(u, w,) = load(a, 0, 3)``: a kernel's stores into a 1-D array
  (its row ``out``, the ``x``, ``p``, packed arguments or out array of a call) and its reads of one
  at constant positions, one call each; ``node_arrays(stack(n * w), n, w)``: a kernel's ``n`` node
  arrays of ``w`` entries on its stack, one call; ``all_finite((v0, v1, ...))``: its check of its
  inputs or outputs, one call. numba types and lowers every subscript and call in Python, one by
  one: with a subscript per entry and a ``math.isfinite`` per value, the first
  ``apex_return("gravity-type0")`` compiled in 4.2 s, with these in 2.5-2.7 s
  (``benchmarks/bench_first_call.py``). In plain Python (a kernel's ``.py_func``) ``load``,
  ``store`` and ``all_finite`` are the subscripts and checks they stand for.
"""

import inspect
import math

from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic, lower_builtin, type_callable


@intrinsic
def stack(typingctx, n):
    """A pointer to ``n`` float64 on the calling function's stack (``n`` a literal integer), allocated
    once in its entry block (LLVM's ``alloca``), so a loop reuses it."""
    if not isinstance(n, types.IntegerLiteral) or n.literal_value < 1:
        return None
    size = n.literal_value

    def codegen(context, builder, signature, args):
        return cgutils.alloca_once(builder, context.get_value_type(types.float64), size=size)

    return types.CPointer(types.float64)(n), codegen


@intrinsic
def node_arrays(typingctx, ptr, n, width):
    """``n`` float64 arrays of ``width`` entries each, one after the other from ``ptr`` (a
    ``stack(n * width)``; ``n`` and ``width`` literal integers), as a tuple: a kernel's node arrays,
    made in one call (``carray(...)[j]`` per array is a subscript numba lowers one by one)."""
    if not (
        isinstance(ptr, types.CPointer)
        and isinstance(n, types.IntegerLiteral)
        and isinstance(width, types.IntegerLiteral)
    ):
        return None
    count, size = n.literal_value, width.literal_value
    arrty = types.Array(types.float64, 1, "C")
    tupty = types.UniTuple(arrty, count)

    def codegen(context, builder, signature, args):
        itemsize = context.get_abi_sizeof(context.get_data_type(types.float64))
        values = []
        for j in range(count):
            view = context.make_array(arrty)(context, builder)
            data = builder.gep(args[0], [context.get_constant(types.intp, j * size)])
            context.populate_array(
                view,
                data=data,
                shape=[context.get_constant(types.intp, size)],
                strides=[context.get_constant(types.intp, itemsize)],
                itemsize=context.get_constant(types.intp, itemsize),
                meminfo=None,
            )
            values.append(view._getvalue())
        return context.make_tuple(builder, tupty, values)

    return tupty(ptr, n, width), codegen


def all_finite(values):
    """Whether every entry of the tuple ``values`` is finite: a kernel's check of its inputs or
    outputs, one call (``math.isfinite(a) & math.isfinite(b) ...`` is a call and an operator per
    entry, each typed and lowered on its own). Plain Python here (a kernel's ``.py_func``)."""
    return all(math.isfinite(v) for v in values)


@type_callable(all_finite)
def _all_finite_type(context):
    def typer(values):
        if isinstance(values, types.BaseTuple) and all(isinstance(t, (types.Float,
                types.Integer)) for t in values):
            return types.boolean
        return None

    return typer


@lower_builtin(all_finite, types.BaseTuple)
def _all_finite_code(context, builder, signature, args):
    result = cgutils.true_bit
    for j, ty in enumerate(signature.args[0]):
        isfinite = context.get_function(math.isfinite, types.boolean(ty))
        result = builder.and_(result, isfinite(builder, [builder.extract_value(args[0], j)]))
    return result


def store(a, values):
    """``a[j] = values[j]`` for every entry of the tuple ``values`` (``a`` a 1-D float array at
    least that long; not checked in compiled code: the lowering sizes the arrays it stores into).
    Plain Python here (a kernel's ``.py_func``); compiled code runs the stores below, in place."""
    for j, v in enumerate(values):
        a[j] = v


def load(a, *index):
    """``(a[i0], a[i1], ...)`` for literal integers ``i0, i1, ...`` (``a`` a 1-D float array; the
    positions are not checked in compiled code: the lowering takes them from the layout that sized
    it). Plain Python here (a kernel's ``.py_func``); compiled code runs the loads below, in place."""
    return tuple(a[i] for i in index)


def _float_row(a) -> bool:
    return isinstance(a, types.Array) and a.ndim == 1 and isinstance(a.dtype, types.Float)


@type_callable(store)
def _store_type(context):
    def typer(a, values):
        if _float_row(a) and isinstance(values, types.BaseTuple):
            if all(isinstance(t, (types.Float, types.Integer)) for t in values):
                return types.none
        return None

    return typer


@lower_builtin(store, types.Array, types.BaseTuple)
def _store_code(context, builder, signature, args):
    aryty, tupty = signature.args
    ary = context.make_array(aryty)(context, builder, args[0])
    for j, ty in enumerate(tupty):
        value = context.cast(builder, builder.extract_value(args[1], j), ty, aryty.dtype)
        at = [context.get_constant(types.intp, j)]
        builder.store(value, cgutils.get_item_pointer(context, builder, aryty, ary, at))
    return context.get_dummy_value()


@type_callable(load)
def _load_type(context):
    def typer(a, *index):
        # numba types the positions as integers, then, on None, as the literals they are; it
        # reads ``typer.pysig`` after this call, so the call lowers with the flat signature (an
        # array and one literal per position) instead of folding the positions into a tuple
        if _float_row(a) and index and all(isinstance(i, types.IntegerLiteral) for i in index):
            typer.pysig = _flat(1 + len(index))
            return types.UniTuple(a.dtype, len(index))
        return None

    return typer


def _flat(n: int) -> inspect.Signature:
    """The Python signature of ``n`` positional-only arguments."""
    P = inspect.Parameter
    return inspect.Signature([P(f"a{j}", P.POSITIONAL_ONLY) for j in range(n)])


@lower_builtin(load, types.Array, types.VarArg(types.IntegerLiteral))
def _load_code(context, builder, signature, args):
    aryty, *index = signature.args
    ary = context.make_array(aryty)(context, builder, args[0])
    values = [
        builder.load(
            cgutils.get_item_pointer(
                context, builder, aryty, ary, [context.get_constant(types.intp, i.literal_value)]
            )
        )
        for i in index
    ]
    return context.make_tuple(builder, signature.return_type, values)


def into_rows(expr, caller, callee):
    """numba's inline cost model of a role kernel (``njit(inline=into_rows)``): inlined at numba's IR
    level into its own batch form ``<kernel>_rows`` only, whose loop then runs the kernel's body
    without a call (Geyer's apex return: 137 -> 130 ns a row from numba's cache); every other caller
    calls it. A first batch then compiles the body once, inside the loop; a first scalar call compiles
    the kernel alone."""
    return caller.func_id.func_name == callee.func_id.func_name + "_rows"


@intrinsic
def row(typingctx, A, i):
    """Row ``i`` of the 2-D float array ``A`` as a 1-D array of the same memory and no meminfo (the
    module docstring); C-contiguous when ``A`` is. ``i`` is not checked: the caller's loop bounds it."""
    if not (isinstance(A, types.Array) and A.ndim == 2 and isinstance(A.dtype, types.Float)):
        return None
    if not isinstance(i, types.Integer):
        return None
    rowty = types.Array(A.dtype, 1, "C" if A.layout == "C" else "A")

    def codegen(context, builder, signature, args):
        aryty = signature.args[0]
        ary = context.make_array(aryty)(context, builder, args[0])
        shape = cgutils.unpack_tuple(builder, ary.shape, 2)
        strides = cgutils.unpack_tuple(builder, ary.strides, 2)
        index = context.cast(builder, args[1], signature.args[1], types.intp)
        first = [index, context.get_constant(types.intp, 0)]
        ptr = cgutils.get_item_pointer2(context, builder, ary.data, shape, strides, aryty.layout, first)
        out = context.make_array(rowty)(context, builder)
        context.populate_array(
            out, data=ptr, shape=[shape[1]], strides=[strides[1]], itemsize=ary.itemsize, meminfo=None
        )
        return out._getvalue()

    return rowty(A, i), codegen


@intrinsic
def fail(typingctx, out, status):
    """A failed row: ``out`` (a 1-D float array) all NaN; returns ``status`` as an int64. Written in
    place at each call (an intrinsic): a function would compile once per status, since numba types
    a status constant as a literal (0.05 s each, 17 of them in a first iterative Jacobian)."""
    if not (
        isinstance(out, types.Array)
        and out.ndim == 1
        and isinstance(out.dtype, types.Float)
        and isinstance(status, types.Integer)
    ):
        return None

    def codegen(context, builder, signature, args):
        aryty = signature.args[0]
        ary = context.make_array(aryty)(context, builder, args[0])
        (n,) = cgutils.unpack_tuple(builder, ary.shape, 1)
        nan = context.get_constant(aryty.dtype, math.nan)
        with cgutils.for_range(builder, n) as loop:
            builder.store(nan, cgutils.get_item_pointer(context, builder, aryty, ary, [loop.index]))
        return args[1]

    return types.int64(out, types.int64), codegen


@njit(cache=True, error_model="numpy")
def finite(out):
    """Whether every entry of ``out`` is finite: one pass without a branch per entry, which LLVM
    vectorizes (a row of a Jacobian, tens of entries, in a few vector compares). Rows of at most
    ``FINITE_CHAIN`` values (derive/lower.py) are checked in registers instead; the wide ones (a
    Jacobian's) by this: against a loop that stops at the first non-finite entry, Geyer's
    apex-return Jacobian 270 -> 231 ns a row on one thread (its stance Jacobian checked inside)."""
    bad = False
    for j in range(out.shape[0]):
        bad |= not math.isfinite(out[j])
    return not bad
