"""SymPy -> Python source printer for numba kernels (numba compiles the ``math`` module's functions).

Floats print with ``repr`` (shortest round-trip form) so regenerated files are byte-identical and
lose no precision; rationals print as exact float literals.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter


class NumbaPrinter(PythonCodePrinter):
    """Prints scalar SymPy expressions as ``math``-module Python that numba's njit compiles."""

    def __init__(self, settings=None):
        super().__init__({"fully_qualified_modules": True, "standard": "python3", **(settings or {})})

    def _print_Rational(self, expr):
        return repr(float(expr.p) / float(expr.q))

    def _print_Half(self, expr):
        return "0.5"

    def _print_Integer(self, expr):
        return f"{int(expr)}.0"

    def _print_Float(self, expr):
        return repr(float(expr))

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp == sp.S.Half:
            return f"math.sqrt({self._print(base)})"
        if exp == -sp.S.Half:
            return f"(1.0/math.sqrt({self._print(base)}))"
        if exp.is_Integer and exp == -1:
            return f"(1.0/{self.parenthesize(base, sp.printing.precedence.PRECEDENCE['Pow'])})"
        if exp.is_Integer:
            # Integer powers stay integer so numba emits repeated multiplication.
            return f"{self.parenthesize(base, sp.printing.precedence.PRECEDENCE['Pow'])}**{int(exp)}"
        if exp.is_Rational and exp.q == 2:
            # b**(n/2) = b**k sqrt(b), k = (|n| - 1)/2: a multiplication and a square root instead of
            # libm's pow (measured: pow was an eighth of the iterative map's Jacobian). Within 1-3
            # ulp of pow (tests/test_codegen.py); the same NaN for b < 0, inf at b = 0 for n < 0.
            b = self.parenthesize(base, sp.printing.precedence.PRECEDENCE["Pow"])
            k = (abs(int(exp.p)) - 1) // 2  # >= 1: the square roots are printed above
            power = f"{b}{'' if k == 1 else f'**{k}'}*math.sqrt({self._print(base)})"
            return f"({power})" if exp > 0 else f"(1.0/({power}))"
        return super()._print_Pow(expr, rational=rational)

    def _print_Abs(self, expr):
        return f"abs({self._print(expr.args[0])})"


_PRINTER = NumbaPrinter()


def to_code(expr) -> str:
    """Python source of one scalar expression."""
    return _PRINTER.doprint(sp.sympify(expr))
