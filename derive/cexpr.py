"""The C99 printer of the lowered kernels' code: expressions and the few statement forms
:mod:`.lower` writes, from their Python form to C.

:func:`.lower.lower` turns a kernel's declaration into template data whose code is in a small
expression language with Python's syntax (what :class:`.printer.NumbaPrinter` prints, plus
subscripts, stack arrays and tuple stores). The numba target renders it as it is; the C target
(:mod:`.ctarget`) prints each piece through this module, which parses it with :mod:`ast` and writes
the C of the same value. Anything outside that language is refused (:class:`CPrintError`), so a new
construct in the lowering fails the C target's generation instead of printing wrong C.

Semantics kept: Python's ``min``/``max`` of floats (``min(a, b)`` is ``b < a ? b : a``: a NaN first
argument stays, unlike C's ``fmin``); integer powers as multiplications (what numba emits);
``int(x)`` truncation toward zero; ``abs`` as ``fabs``; ``math.pi`` as its double literal (C99 has
no ``M_PI``).
"""

from __future__ import annotations

import ast
import re

#: ``math`` functions and the C99 ``<math.h>`` function of the same value.
_MATH = {
    "sqrt": "sqrt",
    "sin": "sin",
    "cos": "cos",
    "tan": "tan",
    "asin": "asin",
    "acos": "acos",
    "atan": "atan",
    "atan2": "atan2",
    "exp": "exp",
    "log": "log",
    "floor": "floor",
    "copysign": "copysign",
    "isfinite": "isfinite",
    "fabs": "fabs",
}
_CONST = {"pi": "3.141592653589793", "nan": "NAN", "inf": "INFINITY"}

#: C keywords and <math.h> names a kernel's local name must not take (they would not compile, or
#: would shadow a function the kernel calls).
C_RESERVED = (
    frozenset(
        "auto break case char const continue default do double else enum extern float for goto if "
        "inline int long register restrict return short signed sizeof static struct switch typedef "
        "union unsigned void volatile while _Bool _Complex _Imaginary".split()
    )
    | frozenset(_MATH.values())
    | {"pow", "NAN", "INFINITY", "fmin", "fmax"}
)


class CPrintError(ValueError):
    """Code outside the language the C printer knows."""


_BIN = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/"}
_CMP = {ast.Lt: "<", ast.LtE: "<=", ast.Gt: ">", ast.GtE: ">=", ast.Eq: "==", ast.NotEq: "!="}


def _status_name(name: str) -> str:
    return "SLIPMAPS_" + name if name.startswith("STATUS_") else name


def _powi(base: str, n: int) -> str:
    """``base**n`` (n >= 1) as repeated multiplication by squaring, as LLVM expands numba's powi."""
    if n == 1:
        return base
    half = _powi(base, n // 2)
    sq = f"({half}*{half})" if n // 2 > 1 else f"({base}*{base})"
    return sq if n % 2 == 0 else f"({sq}*{base})"


class _Printer:
    def expr(self, node: ast.AST) -> str:
        method = getattr(self, "_" + type(node).__name__, None)
        if method is None:
            raise CPrintError(f"no C for {ast.unparse(node)!r} ({type(node).__name__})")
        return method(node)

    def _Constant(self, node):
        v = node.value
        if isinstance(v, bool):
            return "1" if v else "0"
        if isinstance(v, int):
            return str(v)
        if isinstance(v, float):
            if v != v:
                return "NAN"
            if v in (float("inf"), float("-inf")):
                return "INFINITY" if v > 0 else "(-INFINITY)"
            text = repr(v)
            return text if any(c in text for c in ".e") else text + ".0"
        raise CPrintError(f"no C for the constant {v!r}")

    def _Name(self, node):
        if node.id == "NAN":
            return "NAN"
        if node.id in ("True", "False"):
            return "1" if node.id == "True" else "0"
        return _status_name(node.id)

    def _Attribute(self, node):
        if isinstance(node.value, ast.Name) and node.value.id == "math" and node.attr in _CONST:
            return _CONST[node.attr]
        raise CPrintError(f"no C for {ast.unparse(node)!r}")

    def _BinOp(self, node):
        if isinstance(node.op, ast.Pow):
            base = self.expr(node.left)
            exp = node.right
            neg = isinstance(exp, ast.UnaryOp) and isinstance(exp.op, ast.USub)
            inner = exp.operand if neg else exp
            if isinstance(inner, ast.Constant) and isinstance(inner.value, int) and inner.value >= 1:
                b = base if re.fullmatch(r"[A-Za-z_]\w*", base) else f"({base})"
                power = _powi(b, inner.value)
                return f"(1.0/{power})" if neg else f"({power})"
            return f"pow({base}, {self.expr(exp)})"
        if isinstance(node.op, ast.BitAnd):
            # the kernels' checks join truth values with & (one expression for numba); C's isfinite
            # is nonzero, not 1, when true: &&
            return f"({self.expr(node.left)} && {self.expr(node.right)})"
        op = _BIN.get(type(node.op))
        if op is None:
            raise CPrintError(f"no C for the operator in {ast.unparse(node)!r}")
        left, right = node.left, node.right
        if op == "/" and all(isinstance(s, ast.Constant) and type(s.value) is int for s in (left, right)):
            raise CPrintError(f"integer division {ast.unparse(node)!r}")
        return f"({self.expr(left)} {op} {self.expr(right)})"

    def _UnaryOp(self, node):
        if isinstance(node.op, ast.USub):
            return f"(-{self.expr(node.operand)})"
        if isinstance(node.op, ast.UAdd):
            return self.expr(node.operand)
        if isinstance(node.op, ast.Not):
            return f"(!{self.expr(node.operand)})"
        raise CPrintError(f"no C for {ast.unparse(node)!r}")

    def _BoolOp(self, node):
        op = " && " if isinstance(node.op, ast.And) else " || "
        return "(" + op.join(self.expr(v) for v in node.values) + ")"

    def _Compare(self, node):
        parts, left = [], node.left
        for op, right in zip(node.ops, node.comparators, strict=True):
            c = _CMP.get(type(op))
            if c is None:
                raise CPrintError(f"no C for the comparison in {ast.unparse(node)!r}")
            parts.append(f"({self.expr(left)} {c} {self.expr(right)})")
            left = right
        return parts[0] if len(parts) == 1 else "(" + " && ".join(parts) + ")"

    def _IfExp(self, node):
        return f"({self.expr(node.test)} ? {self.expr(node.body)} : {self.expr(node.orelse)})"

    def _Subscript(self, node):
        target = self.expr(node.value)
        index = node.slice
        items = index.elts if isinstance(index, ast.Tuple) else [index]
        return target + "".join(f"[{self.expr(i)}]" for i in items)

    def _Call(self, node):
        f = node.func
        if isinstance(f, ast.Name) and f.id == "all_finite" and isinstance(node.args[0], ast.Tuple):
            # support.all_finite((a, b, ...)): every entry finite
            return f"({' && '.join(f'isfinite({self.expr(a)})' for a in node.args[0].elts)})"
        args = [self.expr(a) for a in node.args]
        if node.keywords:
            raise CPrintError(f"no C for keyword arguments in {ast.unparse(node)!r}")
        if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name) and f.value.id == "math":
            if f.attr not in _MATH:
                raise CPrintError(f"no C for math.{f.attr}")
            return f"{_MATH[f.attr]}({', '.join(args)})"
        if not isinstance(f, ast.Name):
            raise CPrintError(f"no C for the call {ast.unparse(node)!r}")
        if f.id == "abs" and len(args) == 1:
            return f"fabs({args[0]})"
        if f.id in ("min", "max") and len(args) == 2:
            # Python's (and numba's) min/max: the first argument unless the second compares below
            # (above) it, so a NaN first argument stays
            return f"slipmaps_{f.id}_({args[0]}, {args[1]})"
        if f.id == "int" and len(args) == 1:
            return f"((long)({args[0]}))"
        if f.id == "float" and len(args) == 1:
            return f"((double)({args[0]}))"
        return f"{f.id}({', '.join(args)})"


_PRINTER = _Printer()


def cexpr(code: str) -> str:
    """The C of one expression of the lowered code."""
    try:
        tree = ast.parse(code.strip(), mode="eval")
    except SyntaxError as exc:  # pragma: no cover - the lowering prints valid Python
        raise CPrintError(f"cannot parse {code!r}: {exc}") from exc
    return _PRINTER.expr(tree.body)


def _support_call(value: ast.AST, name: str) -> bool:
    """Whether ``value`` is a call of the support module's ``name`` (``store``, ``load``) on a named
    array, with constant positions (``load``)."""
    return (
        isinstance(value, ast.Call)
        and isinstance(value.func, ast.Name)
        and value.func.id == name
        and bool(value.args)
        and isinstance(value.args[0], ast.Name)
        and (name != "load" or all(type(getattr(a, "value", None)) is int for a in value.args[1:]))
    )


def _stack_size(value: ast.AST) -> int | None:
    """``n`` of ``carray(stack(n), n)`` (a stack array of the lowering), else None."""
    if (
        isinstance(value, ast.Call)
        and isinstance(value.func, ast.Name)
        and value.func.id == "carray"
        and isinstance(value.args[0], ast.Call)
        and getattr(value.args[0].func, "id", "") == "stack"
    ):
        return int(value.args[0].args[0].value)
    return None


def cstatements(code: str) -> tuple[list[str], dict[str, int]]:
    """The C statements of lowered statement lines (a stack array, a store or load of the support
    module, a tuple store or unpacking, an assignment) and the stack arrays they declare (name ->
    length; declared by the caller at the top of the function)."""
    out: list[str] = []
    arrays: dict[str, int] = {}
    for stmt in ast.parse(code.strip()).body:
        if isinstance(stmt, ast.Expr) and _support_call(stmt.value, "store"):
            # store(a, (v0, v1, ...)): a[j] = vj; no value reads what the store writes
            array, values = stmt.value.args
            if not isinstance(values, ast.Tuple):
                raise CPrintError(f"no C for {ast.unparse(stmt)!r}")
            for v in values.elts:
                reads = {ast.unparse(n.value) for n in ast.walk(v) if isinstance(n, ast.Subscript)}
                if array.id in reads:
                    raise CPrintError(f"a store reads what it writes: {ast.unparse(stmt)!r}")
            out += [f"{array.id}[{j}] = {cexpr(ast.unparse(v))};" for j, v in enumerate(values.elts)]
            continue
        if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1:
            target, value = stmt.targets[0], stmt.value
            size = _stack_size(value)
            if size is not None and isinstance(target, ast.Name):
                arrays[target.id] = size
                continue
            if isinstance(target, ast.Tuple) and _support_call(value, "load"):
                # (u, w,) = load(a, i, k): u = a[i]; w = a[k]
                array, *index = value.args
                if len(index) != len(target.elts):
                    raise CPrintError(f"no C for {ast.unparse(stmt)!r}")
                out += [
                    f"{cexpr(ast.unparse(t))} = {array.id}[{i.value}];"
                    for t, i in zip(target.elts, index, strict=True)
                ]
                continue
            if isinstance(target, ast.Tuple):
                if not isinstance(value, ast.Tuple) or len(value.elts) != len(target.elts):
                    raise CPrintError(f"no C for {ast.unparse(stmt)!r}")
                # every value reads nothing the stores write (a row stored, inputs unpacked)
                written = {ast.unparse(t) for t in target.elts}
                for v in value.elts:
                    if any(ast.unparse(n) in written for n in ast.walk(v) if isinstance(n, ast.Subscript)):
                        raise CPrintError(f"a tuple store reads what it writes: {ast.unparse(stmt)!r}")
                out += [
                    f"{cexpr(ast.unparse(t))} = {cexpr(ast.unparse(v))};"
                    for t, v in zip(target.elts, value.elts, strict=True)
                ]
                continue
            out.append(f"{cexpr(ast.unparse(target))} = {cexpr(ast.unparse(value))};")
            continue
        if isinstance(stmt, ast.AugAssign) and isinstance(stmt.op, (ast.Add, ast.Sub)):
            op = "+=" if isinstance(stmt.op, ast.Add) else "-="
            out.append(f"{cexpr(ast.unparse(stmt.target))} {op} {cexpr(ast.unparse(stmt.value))};")
            continue
        raise CPrintError(f"no C for the statement {ast.unparse(stmt)!r}")
    return out, arrays
